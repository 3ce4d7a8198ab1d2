"""pseudoshadow: render the pseudo-shadow of a haptic probe on virtual surfaces, headless.

    import pseudoshadow
    r = pseudoshadow.Renderer(scene="scenes/table4_1_e.toml", backend="egl",
                              set={"render.size": [128, 128]})
    r.set("materials.table4_1_e.lambda_min", 0.4)
    f = r.render(probe=(2, 0, 7.5), velocity=(0, 150, 0), frames=2, aovs=["distance"])
    f.color            # numpy uint8, height x width x 3: the bytes of `render --out x.png`
    f.aovs["distance"] # numpy float32, height x width (mm; NaN where no probe is above)
    f.stats            # dict: the JSON of `render --stats FILE`

Errors raise pseudoshadow.Error (a RuntimeError) with the command line's message, e.g.
"scene.toml:12: ..." or "--set materials.wood.lambda_mn: unknown key; close matches: ...".
The C++ API it wraps and every decision: docs/api.md.
"""

import json
import math
import os

from ._core import Error, aov_names
from ._core import Renderer as _CoreRenderer
from ._core import read_image as _read_image

Error.__module__ = "pseudoshadow"  # shown as pseudoshadow.Error in tracebacks

__all__ = ["Error", "Frame", "Renderer", "aov_names", "read_image", "toml_value"]


def toml_value(value):
    """The TOML text of a Python value, as `--set KEY=VALUE` takes it."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)  # the shortest text that reads back as the same double
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string: JSON's escapes are TOML's
    if isinstance(value, (list, tuple)):
        return "[" + ",".join(toml_value(v) for v in value) + "]"
    if hasattr(value, "tolist"):  # numpy scalars and arrays
        return toml_value(value.tolist())
    raise TypeError(f"cannot write {type(value).__name__} as a scene value: "
                    "use a number, bool, string or a list of them")


class Frame:
    """The last frame of a render() call: colour, the AOVs asked for, and the stats."""

    def __init__(self, raw):
        self.color = raw["color"]
        self.aovs = raw["aovs"]
        self.stats = json.loads(raw["stats_json"])

    def __repr__(self):
        h, w = self.color.shape[:2]
        return f"<pseudoshadow.Frame {w}x{h} aovs={sorted(self.aovs)}>"


class Renderer:
    """A scene on a headless OpenGL 4.5 context (EGL or OSMesa).

    scene: a scene file's path; None for the built-in default scene.
    scene_text: scene TOML given as a string instead (relative files resolve against base_dir,
      default the current directory).
    backend: "auto" (EGL, then OSMesa), "egl" or "osmesa".
    gpu: the EGL display, as the CLI's --gpu: None (Mesa's surfaceless platform), "auto" (a
      hardware EGL device, else surfaceless, else OSMesa), "software" (Mesa's software EGL
      device) or a device number; stats["egl_device"] says which was taken.
    set: scene overrides applied when the scene is parsed, as {path: value} or ["path=value", ...].
    allow_paths: more folders the scene may read files from (the CLI's --allow-path). A scene may
      read only files in its own folder tree (base_dir's for scene_text) and the shipped data, so
      that a submitted scene cannot read the server's other files; values in `set` are yours and
      are not confined.
    """

    def __init__(self, scene=None, backend="auto", set=None, scene_text=None, base_dir="", gpu=None,
                 allow_paths=None):
        if scene is not None and scene_text is not None:
            raise ValueError("give scene (a file) or scene_text, not both")
        gpu_text = "" if gpu is None else str(gpu)
        allow = [os.fspath(p) for p in (allow_paths or [])]
        sets = []
        if isinstance(set, dict):
            sets = [f"{k}={toml_value(v)}" for k, v in set.items()]
        elif set is not None:
            sets = [str(s) for s in set]
        if scene_text is not None:
            self._r = _CoreRenderer.open("string", scene_text, str(base_dir), backend, sets, gpu_text, allow)
        elif scene is not None:
            self._r = _CoreRenderer.open("file", os.fspath(scene), "", backend, sets, gpu_text, allow)
        else:
            self._r = _CoreRenderer.open("default", "", "", backend, sets, gpu_text, allow)

    def close(self):
        """Release the renderer now; with the last one open, its GL context too, after which
        another backend may be opened (a process has one GL backend at a time). Also done
        when the renderer is garbage-collected, or on leaving a `with` block."""
        self._r = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @property
    def _core(self):
        if self._r is None:
            raise Error("this renderer was closed; open a new pseudoshadow.Renderer")
        return self._r

    def set(self, key, value=None):
        """Change scene values by their paths, as --set: set("materials.wood.lambda_min", 0.4),
        set("materials.wood.lambda_min=0.4"), or several checked together (one rebuild; on an
        error none applies): set({"materials.wood.lambda_min": 0.4, "materials.wood.lambda_max": 0.6}).
        The probe keeps its position and velocity unless these keys set them."""
        if isinstance(key, dict):
            if value is not None:
                raise TypeError("set(dict) takes no value")
            self._core.set([f"{k}={toml_value(v)}" for k, v in key.items()])
        elif value is None:
            self._core.set([str(key)])
        else:
            self._core.set([f"{key}={toml_value(value)}"])

    def set_probe(self, position, velocity):
        """Move the probe (mm) and set its velocity (mm/s) without rendering."""
        self._core.set_probe(tuple(position), tuple(velocity))

    def nearest_surface(self, points, max_distance_mm=1000.0):
        """The nearest point of the scene's touchable surfaces to each point (mm): the geometry
        the probe feels, as the scene file places it (hidden surfaces included, a button a hole in
        its face). points: one (x, y, z) or an N x 3 array. Returns (distance, point, normal) as
        numpy arrays (N; N x 3; N x 3): distance is inf, point and normal 0, where no surface is
        within max_distance_mm. March a ray by these distances to find what lies under a pixel
        (tools/pointing_points.py does)."""
        import numpy as np
        pts = np.asarray(points, dtype=np.float64)
        single = pts.ndim == 1
        distance, point, normal = self._core.nearest_surface(pts.reshape(-1, 3), float(max_distance_mm))
        if single:
            return distance[0], point[0], normal[0]
        return distance, point, normal

    @property
    def size(self):
        """(width, height) in pixels."""
        return self._core.size()

    @property
    def probe(self):
        """(position, velocity) of the probe now."""
        return self._core.probe()

    def render(self, probe=None, velocity=None, frames=None, aovs=()):
        """Render `frames` frames (the probe moves by each frame's displacement; None: the
        scene's render.frames, as the CLI without --frames) and return the last as a Frame.
        aovs: names from aov_names(), or "all"."""
        names = aov_names() if aovs == "all" else [str(a) for a in aovs]
        raw = self._core.render(None if probe is None else tuple(probe),
                             None if velocity is None else tuple(velocity),
                             0 if frames is None else int(frames), names)
        return Frame(raw)


def read_image(path):
    """An image file read by pseudoshadow's own reader (PNG; EXR and others through
    OpenImageIO): float32, height x width (x channels); 8-bit files as k/255."""
    return _read_image(os.fspath(path))
