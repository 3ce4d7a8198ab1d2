"""The Python module against the command line: the same scene, overrides, probe and frame count
must give the CLI's PNG bytes, its EXR floats and its --stats JSON exactly, and the same error
messages. Run by CTest once per headless backend (python.pytest.egl, python.pytest.osmesa):
PS_TEST_BACKEND names it, PS_CLI is the pseudoshadow binary of the same build, PS_SOURCE_DIR
the source tree (its scenes and examples). Images are 64x64 to keep the suite cheap."""

import gc
import importlib.util
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import pseudoshadow as ps

BACKEND = os.environ.get("PS_TEST_BACKEND", "auto")
CLI = os.environ.get("PS_CLI", "pseudoshadow")
SOURCE = Path(os.environ.get("PS_SOURCE_DIR", Path(__file__).resolve().parents[2]))
SCENES = SOURCE / "scenes"
SIZE = {"render.size": [64, 64]}
# Wall times differ between any two runs; everything else in --stats must be equal.
TIME_KEYS = {"timings_ms", "gpu_timings_ms", "gabor_bake_ms", "gabor_tiles_ready_ms", "first_frame_ms"}


def cli(*args, cwd):
    return subprocess.run([CLI, *map(str, args), "--backend", BACKEND], cwd=cwd,
                          capture_output=True, text=True, check=False)


def png_bytes(path):
    """The 8-bit samples of a PNG, through pseudoshadow's reader (k/255 floats)."""
    pixels = ps.read_image(path)
    assert pixels.dtype == np.float32
    return np.rint(pixels * 255.0).astype(np.uint8)


def assert_same(got, want, what):
    """Exact equality (NaN equals NaN), with a short message instead of two array dumps."""
    assert got.shape == want.shape, f"{what}: shape {got.shape} vs {want.shape}"
    same = (got == want) | (np.isnan(got) & np.isnan(want)) if got.dtype.kind == "f" else got == want
    if not same.all():
        diff = np.abs(got.astype(np.float64) - want.astype(np.float64))
        raise AssertionError(f"{what}: {np.count_nonzero(~same)} of {same.size} values differ, "
                             f"max |difference| {np.nanmax(diff)}")


def without_times(stats):
    return {k: v for k, v in stats.items() if k not in TIME_KEYS}


def test_import_lists_the_aovs():
    assert ps.aov_names() == ["intensity", "distance", "texture", "normal", "displacement"]


def test_frame_equals_the_cli_png_exr_and_stats(tmp_path):
    aov_files = {name: f"{name}.exr" for name in ps.aov_names()}
    args = ["render", "--size", "64x64", "--set", "materials.wood.lambda_min=0.4",
            "--probe", "2,0,7.5", "--velocity", "0,150,0", "--frames", "3",
            "--out", "color.png", "--stats", "stats.json", "-q"]
    for name, file in aov_files.items():
        args += ["--aov", f"{name}={file}"]
    run = cli(*args, cwd=tmp_path)
    assert run.returncode == 0, run.stderr

    r = ps.Renderer(backend=BACKEND, set=SIZE)
    r.set("materials.wood.lambda_min", 0.4)
    f = r.render(probe=(2, 0, 7.5), velocity=(0, 150, 0), frames=3, aovs="all")

    assert f.color.dtype == np.uint8 and f.color.shape == (64, 64, 3)
    assert_same(f.color, png_bytes(tmp_path / "color.png"), "colour vs the CLI's PNG")
    for name, file in aov_files.items():
        exr = ps.read_image(tmp_path / file)
        got = f.aovs[name]
        assert got.dtype == np.float32, name
        assert_same(got, exr, f"AOV {name} vs the CLI's EXR")
    # Not a vacuous comparison: a shadow with texture, and NaN distance outside it.
    assert f.aovs["intensity"].max() == 1.0
    assert np.isnan(f.aovs["distance"]).any() and np.isfinite(f.aovs["distance"]).any()
    assert np.count_nonzero(f.aovs["texture"]) > 100

    cli_stats = json.loads((tmp_path / "stats.json").read_text())
    assert without_times(f.stats) == without_times(cli_stats)
    assert f.stats["backend"] == (BACKEND if BACKEND != "auto" else cli_stats["backend"])
    assert f.stats["frames"] == 3 and f.stats["shadow_pixels"] > 0


SHIPPED = sorted(p.relative_to(SCENES).as_posix() for p in SCENES.glob("**/*.toml")
                 if p.parent.name not in ("materials", "maze", "studies"))  # materials; the maze's and the studies' own files


@pytest.mark.parametrize("scene", SHIPPED)
def test_every_shipped_scene_first_frame_equals_the_cli(scene, tmp_path):
    """The library's first frame is built like `render`'s: the world as the scene starts it
    (bodies, charges, bands) included, so the bytes are the CLI's for every shipped scene."""
    run = cli("render", "--scene", SCENES / scene, "--size", "64x64", "--out", "c.png", "-q", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    got = ps.Renderer(scene=SCENES / scene, backend=BACKEND, set=SIZE).render()
    assert_same(got.color, png_bytes(tmp_path / "c.png"), f"{scene}: the library's colour vs the CLI's PNG")


def test_later_renders_continue_from_the_pushed_probe():
    r = ps.Renderer(backend=BACKEND, set=SIZE)  # default scene: the probe 1 mm into the plank
    z0 = 7.0
    first = r.render()
    z1 = first.stats["probe_position"][2]
    assert z1 > z0  # pushed out of the surface
    assert r.probe[0][2] == z1
    second = r.render()
    assert second.stats["max_penetration"] < first.stats["max_penetration"]
    assert second.stats["probe_position"][2] > z1
    # A given pose starts from there again.
    third = r.render(probe=(0, 0, z0))
    assert third.stats["max_penetration"] > second.stats["max_penetration"]


def test_set_changes_the_image_and_a_bad_set_changes_nothing(tmp_path):
    r = ps.Renderer(backend=BACKEND, set=SIZE)
    before = r.render(probe=(0, 0, 7), frames=1)
    r.set("materials.wood.lambda_min", 0.4)
    after = r.render(probe=(0, 0, 7), frames=1)
    assert np.count_nonzero(before.color != after.color) > 50

    with pytest.raises(ps.Error) as err:
        r.set("materials.wood.lambda_mn", 0.4)
    message = str(err.value)
    assert message.startswith("--set materials.wood.lambda_mn: unknown key")
    run = cli("render", "--set", "materials.wood.lambda_mn=0.4", "--out", "x.png", cwd=tmp_path)
    assert run.returncode == 2 and message in run.stderr

    with pytest.raises(ps.Error, match=r"--set render\.size"):
        r.set("render.size", [0, 64])
    assert r.size == (64, 64)
    again = ps.Renderer(backend=BACKEND, set=SIZE)
    again.set("materials.wood.lambda_min=0.4")
    assert np.array_equal(again.render(probe=(0, 0, 7)).color, after.color)


def test_scene_errors_carry_file_and_line_like_the_cli(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text((SCENES / "table4_1_a.toml").read_text().replace(
        "radius_mm = 25.0", "radius_mm = -25.0"))
    line = next(i for i, text in enumerate(bad.read_text().splitlines(), 1) if "-25.0" in text)
    with pytest.raises(ps.Error) as err:
        ps.Renderer(scene=bad, backend=BACKEND)
    message = str(err.value)
    assert message.startswith(f"{bad}:{line}:"), message
    run = cli("render", "--scene", bad, "--out", "x.png", cwd=tmp_path)
    assert run.returncode == 1 and message in run.stderr

    with pytest.raises(ps.Error, match=r"^<string>:2: unknown key 'radius' in \[probe\]"):
        ps.Renderer(scene_text="[probe]\nradius = 1\n", backend=BACKEND)
    with pytest.raises(ps.Error, match="unknown AOV 'depth'"):
        ps.Renderer(backend=BACKEND, set=SIZE).render(aovs=["depth"])
    with pytest.raises(ps.Error, match="unknown backend 'vulkan'"):
        ps.Renderer(backend="vulkan")


def test_a_scene_reads_only_its_own_folder_unless_allowed(tmp_path):
    """A submitted scene cannot make a server read other files (docs/scene-format.md, "Files a
    scene may read"): refused with the --allow-path that admits it, as the CLI; allow_paths
    admits it; the same file given in `set` is the caller's own."""
    (tmp_path / "private").mkdir()
    (tmp_path / "shared").mkdir()
    lut = tmp_path / "private" / "curve.lut"
    lut.write_text((SOURCE / "textures" / "intensity_thesis.lut").read_text())
    text = f'[materials.wood]\nintensity_lut = "{lut}"\n\n[[surfaces]]\nmaterial = "wood"\n'
    with pytest.raises(ps.Error, match=r"^<string>:2: 'intensity_lut' names .*outside the scene's folder"
                                       r".*--allow-path " + str(tmp_path / "private")):
        ps.Renderer(scene_text=text, base_dir=tmp_path / "shared", backend=BACKEND, set=SIZE)
    allowed = ps.Renderer(scene_text=text, base_dir=tmp_path / "shared", backend=BACKEND, set=SIZE,
                          allow_paths=[tmp_path / "private"])
    plain = '[materials.wood]\n\n[[surfaces]]\nmaterial = "wood"\n'
    by_set = ps.Renderer(scene_text=plain, base_dir=tmp_path / "shared", backend=BACKEND,
                         set={**SIZE, "materials.wood.intensity_lut": str(lut)})
    assert np.array_equal(allowed.render().color, by_set.render().color)


def test_scene_text_renders_as_its_file():
    path = SCENES / "table4_1_a.toml"
    from_file = ps.Renderer(scene=path, backend=BACKEND, set=SIZE).render(aovs=["texture"])
    from_text = ps.Renderer(scene_text=path.read_text(), base_dir=SCENES, backend=BACKEND,
                            set=SIZE).render(aovs=["texture"])
    assert np.array_equal(from_file.color, from_text.color)
    assert np.array_equal(from_file.aovs["texture"], from_text.aovs["texture"])


def test_close_releases_the_backend_for_another():
    # Renderers of earlier tests may still be held by the tracebacks of the errors they raised
    # (reference cycles), which only the cycle collector frees.
    gc.collect()
    other = "osmesa" if BACKEND == "egl" else "egl"
    with ps.Renderer(backend=BACKEND, set=SIZE) as r:
        r.render()
        with pytest.raises(ps.Error, match=f"backend {other}: a renderer on .* is open"):
            ps.Renderer(backend=other)
    with pytest.raises(ps.Error, match="this renderer was closed"):
        r.render()
    assert ps.Renderer(backend=other, set=SIZE).render().stats["backend"] == other


def test_gpu_software_device_gives_the_surfaceless_image():
    # Mesa's software EGL device is llvmpipe behind another display: the same bytes (issue 29).
    if BACKEND == "osmesa":
        pytest.skip("EGL devices are EGL's")
    gc.collect()
    with ps.Renderer(backend="egl", set=SIZE) as r:
        plain = r.render()
    assert plain.stats["egl_device"] == "surfaceless"
    try:
        with ps.Renderer(backend="egl", gpu="software", set=SIZE) as r:
            on_device = r.render()
    except ps.Error as e:
        if "no software EGL device" in str(e):
            pytest.skip(str(e))
        raise
    assert on_device.stats["egl_device"].startswith("device ")
    assert np.array_equal(plain.color, on_device.color)
    assert set(on_device.stats["gpu_timings_ms"]) >= {"surface", "frame"}
    with pytest.raises(ps.Error, match="gpu \"cuda\": expected"):
        ps.Renderer(gpu="cuda")


def test_lambda_sweep_example_measures_the_wavelength_it_sets():
    spec = importlib.util.spec_from_file_location(
        "lambda_sweep", SOURCE / "examples" / "python" / "lambda_sweep.py")
    sweep = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(sweep)
    lambdas = [2.0, 3.0]
    measured = sweep.measure(lambdas, size=128, backend=BACKEND)
    assert measured[0] < measured[1]
    for set_mm, got_mm in zip(lambdas, measured):
        assert got_mm == pytest.approx(set_mm, rel=sweep.tolerance(set_mm))


def test_nearest_surface_is_the_felt_sphere_in_closed_form():
    # A sphere of 20 mm at (5, -3, 10): the distance from p is |p - c| - 20, the point on the ray
    # from c through p, the normal along it. Analytic geometry: exact up to rounding (1e-9 mm).
    text = """
[camera]
position = [0.0, -200.0, 50.0]
target = [0.0, 0.0, 0.0]
up = [0.0, 0.0, 1.0]
[probe]
radius_mm = 4.0
position = [0.0, 0.0, 60.0]
[materials.m]
albedo = [0.5, 0.5, 0.5]
[[surfaces]]
type = "sphere"
material = "m"
center = [5.0, -3.0, 10.0]
radius_mm = 20.0
"""
    r = ps.Renderer(scene_text=text, backend=BACKEND, set=SIZE)
    c = np.array([5.0, -3.0, 10.0])
    pts = np.array([[5.0, -3.0, 40.0], [45.0, 27.0, 10.0], [0.0, 0.0, 0.0], [5.0, -3.0, 3000.0]])
    distance, point, normal = r.nearest_surface(pts)
    want = np.linalg.norm(pts[:3] - c, axis=1) - 20.0
    assert np.allclose(distance[:3], np.abs(want), atol=1e-9)
    out = (pts[:2] - c) / np.linalg.norm(pts[:2] - c, axis=1, keepdims=True)
    assert np.allclose(point[:2], c + 20.0 * out, atol=1e-9)
    assert np.allclose(normal[:2], out, atol=1e-9)
    assert np.isinf(distance[3]) and not point[3].any()
    one = r.nearest_surface((5.0, -3.0, 40.0))
    assert one[0] == pytest.approx(10.0, abs=1e-9)
    with pytest.raises(ps.Error, match="max_distance_mm must be a positive"):
        r.nearest_surface(pts, max_distance_mm=-1)
