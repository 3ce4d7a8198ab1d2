#include "measure/texture_aliasing.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "render/renderer.h"

namespace ps::aliasing {

namespace {

// One plain Gabor texture of wavelength kLambdaMm, far inside its influence distance.
Material plain_material(GaborParams::Strategy strategy, GaborParams::Filter filter) {
  Material m;
  m.name = "plain";
  m.onset_distance_mm = 1e4;
  m.influence_distance_mm = 1e5;
  m.gabor.lambda_min_mm = m.gabor.lambda_max_mm = kLambdaMm;
  m.gabor.theta_min_rad = 0.0;
  m.gabor.theta_max_rad = std::numbers::pi;
  m.gabor.n_min = 10.0;
  m.gabor.n_max = 20.0;
  m.gabor.strategy = strategy;
  // The bilinear tile needs 24 samples per lambda for the 1 % bar, the Hermite one 16.
  m.gabor.bake_samples_per_lambda = strategy == GaborParams::Strategy::kBakedLinear ? 24 : 16;
  m.gabor.filter = filter;
  return m;
}

// The camera that sees the texture's wavelength at lambda_px pixels across the image's centre.
void place_camera(Camera& c, View view, double lambda_px, int size) {
  c.target = {0.0, 0.0, 0.0};
  c.near_mm = 1.0;
  c.far_mm = 5000.0;
  if (view == View::kTopDown) {
    c.projection = Projection::kOrthographic;
    c.position = {0.0, 0.0, 100.0};
    c.up = {0.0, 1.0, 0.0};
    c.ortho_height_mm = kLambdaMm * size / lambda_px;
  } else {
    // Across the centre a pixel spans 2 D tan(5 deg) / size mm at the distance D.
    c.projection = Projection::kPerspective;
    c.fov_y_deg = 10.0;
    const double dist = kLambdaMm * size / (2.0 * std::tan(5.0 * std::numbers::pi / 180.0) * lambda_px);
    const double a = 15.0 * std::numbers::pi / 180.0;
    c.position = {0.0, -dist * std::cos(a), dist * std::sin(a)};
    c.up = {0.0, 0.0, 1.0};
  }
}

}  // namespace

Scene scene(View view, double lambda_px, int size, int render_size, GaborParams::Strategy strategy,
            GaborParams::Filter filter) {
  Scene s;
  s.path = "<texture aliasing>";
  s.render.width = s.render.height = render_size;
  s.materials.push_back(plain_material(strategy, filter));
  Surface p;
  p.type = SurfaceType::kPlane;
  p.material = "plain";
  p.material_index = 0;
  p.size_mm = {1200.0, 1200.0};
  p.resolution = 4;
  s.surfaces.push_back(p);
  s.probe.shape = ProbeShape::kSphere;
  s.probe.radius_mm = 500.0;
  s.probe.position = {0.0, 0.0, 500.5};
  place_camera(s.camera, view, lambda_px, size);
  return s;
}

Result<Image> render_texture(const Scene& s, const Renderer* reuse, std::unique_ptr<Renderer>* keep) {
  RendererOptions o;
  o.reuse_tiles_from = reuse;
  auto r = Renderer::create(s, o);
  if (!r) return r.error();
  if (Status st = r.value()->render_frame(); !st) return st.error();
  auto tex = r.value()->read_aov("texture");
  if (!tex) return tex.error();
  auto inten = r.value()->read_aov("intensity");
  if (!inten) return inten.error();
  for (int y = 0; y < inten->height; ++y)
    for (int x = 0; x < inten->width; ++x)
      if (!(inten->at(x, y, 0) > 0.0f))
        return make_error("texture aliasing: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                          ") is outside the shadow; the comparison needs the texture everywhere");
  if (keep) *keep = std::move(r.value());
  return std::move(tex.value());
}

std::vector<double> box_down(const Image& big, int size) {
  std::vector<double> out(static_cast<size_t>(size) * size, 0.0);
  for (int y = 0; y < size * kSuper; ++y)
    for (int x = 0; x < size * kSuper; ++x) out[(y / kSuper) * size + x / kSuper] += big.at(x, y, 0);
  for (double& v : out) v /= kSuper * kSuper;
  return out;
}

Compare compare(const Image& test, const std::vector<double>& ref) {
  const int n = test.width * test.height;
  double mr = 0.0, mt = 0.0;
  for (int i = 0; i < n; ++i) mr += ref[i], mt += test.at(i % test.width, i / test.width, 0);
  mr /= n, mt /= n;
  double vr = 0.0, vt = 0.0, e2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double t = test.at(i % test.width, i / test.width, 0);
    vr += (ref[i] - mr) * (ref[i] - mr), vt += (t - mt) * (t - mt), e2 += (t - ref[i]) * (t - ref[i]);
  }
  return {std::sqrt(e2 / vr), vt / vr};
}

}  // namespace ps::aliasing
