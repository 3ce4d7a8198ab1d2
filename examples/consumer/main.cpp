// Renders the built-in default scene (or SCENE.toml) through the installed C++ API and writes the
// last frame's colour as a binary PPM: consumer OUT.ppm [auto|egl|osmesa] [SCENE.toml].
// Prints the stats' main numbers; a failure is pseudoshadow::Error's one line and exit 1.
#include <cstdio>
#include <fstream>
#include <string>

#include <pseudoshadow/pseudoshadow.h>

namespace {

pseudoshadow::Backend backend_from(const std::string& name) {
  if (name == "egl") return pseudoshadow::Backend::kEgl;
  if (name == "osmesa") return pseudoshadow::Backend::kOsmesa;
  return pseudoshadow::Backend::kAuto;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: consumer OUT.ppm [auto|egl|osmesa] [SCENE.toml]\n");
    return 2;
  }
  try {
    pseudoshadow::OpenDesc desc;
    desc.backend = backend_from(argc > 2 ? argv[2] : "auto");
    desc.set = {"render.size=[64,64]"};
    pseudoshadow::Renderer renderer = argc > 3 ? pseudoshadow::Renderer::open_file(argv[3], desc)
                                               : pseudoshadow::Renderer::open_default(desc);
    renderer.set("materials.wood.lambda_min", "0.4");
    const pseudoshadow::Frame frame =
        renderer.render({.probe = pseudoshadow::Vec3{2, 0, 7.5}, .velocity = pseudoshadow::Vec3{0, 150, 0},
                         .frames = 2, .aovs = {"distance"}});

    std::ofstream out(argv[1], std::ios::binary);
    out << "P6\n" << frame.width << " " << frame.height << "\n255\n";
    out.write(reinterpret_cast<const char*>(frame.color.data()), static_cast<std::streamsize>(frame.color.size()));
    if (!out) {
      std::fprintf(stderr, "consumer: cannot write %s\n", argv[1]);
      return 1;
    }
    const pseudoshadow::Stats& s = frame.stats;
    std::printf("%dx%d on %s: %u shadow pixels, max penetration %.4f mm, probe at z %.4f mm\n",
                frame.width, frame.height, s.backend.c_str(), s.shadow_pixels, s.max_penetration_mm,
                s.probe_position[2]);
  } catch (const pseudoshadow::Error& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
  return 0;
}
