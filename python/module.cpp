// pseudoshadow._core: the C++ API (include/pseudoshadow/pseudoshadow.h) for Python. Images
// become numpy arrays (colour uint8 H x W x 3; an AOV float32 H x W, or H x W x C for C > 1),
// pseudoshadow::Error becomes pseudoshadow.Error (a RuntimeError) with the CLI's message. The
// friendlier signatures (keyword arguments, Python values for set()) are in __init__.py.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "pseudoshadow/pseudoshadow.h"

namespace py = pybind11;
namespace psa = pseudoshadow;

namespace {

// A copy of `values` shaped height x width (x channels when channels > 1).
template <class T>
py::array_t<T> image_array(const std::vector<T>& values, int width, int height, int channels) {
  std::vector<py::ssize_t> shape = {height, width};
  if (channels > 1) shape.push_back(channels);
  py::array_t<T> array(shape);
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

psa::Backend parse_backend(const std::string& name) {
  if (name == "auto") return psa::Backend::kAuto;
  if (name == "egl") return psa::Backend::kEgl;
  if (name == "osmesa") return psa::Backend::kOsmesa;
  throw psa::Error("--backend: unknown backend '" + name + "' (use auto, egl or osmesa)");
}

py::dict frame_dict(const psa::Frame& f) {
  py::dict aovs;
  for (const psa::Aov& a : f.aovs) aovs[py::str(a.name)] = image_array(a.pixels, f.width, f.height, a.channels);
  py::dict out;
  out["color"] = image_array(f.color, f.width, f.height, 3);
  out["aovs"] = aovs;
  out["stats_json"] = f.stats.json;
  return out;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "pseudoshadow's renderer (C++); use the pseudoshadow package";
  py::register_exception<psa::Error>(m, "Error", PyExc_RuntimeError);

  py::class_<psa::Renderer>(m, "Renderer")
      .def_static("open", [](const std::string& kind, const std::string& source, const std::string& base_dir,
                             const std::string& backend, const std::vector<std::string>& sets,
                             const std::string& gpu, const std::vector<std::string>& allow_paths) {
        psa::OpenDesc desc;
        desc.backend = parse_backend(backend);
        desc.gpu = gpu;
        desc.set = sets;
        desc.allow_paths = allow_paths;
        if (kind == "file") return psa::Renderer::open_file(source, desc);
        if (kind == "string") return psa::Renderer::open_string(source, "<string>", base_dir, desc);
        return psa::Renderer::open_default(desc);
      })
      .def("set", [](psa::Renderer& r, const std::vector<std::string>& key_values) { r.set_all(key_values); })
      .def("set_probe", &psa::Renderer::set_probe)
      .def("size", &psa::Renderer::size)
      .def("probe", &psa::Renderer::probe)
      .def("nearest_surface",
           [](const psa::Renderer& r, py::array_t<double, py::array::c_style | py::array::forcecast> points,
              double max_distance_mm) {
             if (points.ndim() != 2 || points.shape(1) != 3)
               throw psa::Error("nearest_surface: points must be an N x 3 array of mm");
             const py::ssize_t n = points.shape(0);
             std::vector<psa::Vec3> in(static_cast<size_t>(n));
             const double* p = points.data();
             for (py::ssize_t i = 0; i < n; ++i) in[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
             std::vector<psa::SurfacePoint> found;
             {
               py::gil_scoped_release release;  // a mesh's queries take a while for many points
               found = r.nearest_surface(in, max_distance_mm);
             }
             py::array_t<double> distance(n), point({n, py::ssize_t{3}}), normal({n, py::ssize_t{3}});
             double* d = distance.mutable_data();
             double* q = point.mutable_data();
             double* m = normal.mutable_data();
             for (py::ssize_t i = 0; i < n; ++i) {
               d[i] = found[i].distance_mm;
               for (int k = 0; k < 3; ++k) {
                 q[3 * i + k] = found[i].point[k];
                 m[3 * i + k] = found[i].normal[k];
               }
             }
             return py::make_tuple(distance, point, normal);
           })
      .def("render", [](psa::Renderer& r, std::optional<psa::Vec3> probe, std::optional<psa::Vec3> velocity,
                        int frames, const std::vector<std::string>& aovs) {
        psa::RenderDesc desc{probe, velocity, frames, aovs};
        psa::Frame frame;
        {
          py::gil_scoped_release release;  // the frames take a while; other Python threads may run
          frame = r.render(desc);
        }
        return frame_dict(frame);
      });

  m.def("aov_names", &psa::aov_names);
  m.def("read_image", [](const std::string& path) {
    const psa::ImageData image = psa::read_image(path);
    return image_array(image.pixels, image.width, image.height, image.channels);
  });
}
