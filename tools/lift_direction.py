#!/usr/bin/env python3
"""Along the surface's normal or back along the view ray: where the pseudo-shadow lands for each.

    PYTHONPATH=build/python tools/lift_direction.py [--hover-mm 1] [SCENE ...]

For each rest point of a scene's pointing walk (tests/window/walks/pointing/<scene>.walk: the
points the window walks rest the pointer on), the surface point S under the pixel is found by
marching its ray on the felt geometry (Renderer.nearest_surface), and the probe is put h above S
in two ways:
  - along the normal: its centre at S + (R + h) m, m the drawn normal at the pixel (the mapping's
    rule, docs/window.md "Over a slope");
  - along the view ray: its centre on the pointer's line of sight, R + h from the nearest surface
    (the probe stays under the pointer as the eye sees it).
One frame is drawn for each and the shadow's core is measured as the window measures it; the
table gives, per scene, the largest and the mean distance from the pointer's pixel in pixels.
Orthographic scenes are left out: there the view ray is the plane's normal and both are one.
Writes a Markdown table on stdout. About a minute for all the scenes on 2 cores.
"""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pointing_points as pp  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def walk_points(path):
    """The rest points of a pointing walk: each sweep's end, (x, y) as fractions of the window."""
    pts = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            w = line.split("#", 1)[0].split()
            if w and w[0] == "sweep":
                pts.append((float(w[3]), float(w[4])))
    return pts[:-1] if len(pts) > 1 and pts[-1] == (0.5, 0.5) else pts


def scene_for(name):
    for folder in ("scenes", "scenes/universe", "scenes/fourd"):
        path = os.path.join(REPO, folder, name + ".toml")
        if os.path.exists(path):
            return path
    return None


def along_ray(renderer, eye, direction, s, reach):
    """The point on the line from S back toward the eye at distance `reach` from the nearest surface
    (bisection: the distance grows from 0 at S)."""
    lo, hi = 0.0, float(np.linalg.norm(s - eye)) - 1e-3
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        d, _, _ = renderer.nearest_surface(s - mid * direction)
        if d < reach:
            lo = mid
        else:
            hi = mid
    return s - hi * direction


def measure(scene, points, hover_mm):
    import pseudoshadow
    doc = pp.load(scene)
    cam = doc["camera"]
    if cam.get("projection", "perspective") != "perspective":
        return None
    r = pseudoshadow.Renderer(scene)
    first = r.render(aovs=["normal"])
    normal = first.aovs["normal"]
    h, w = normal.shape[:2]
    radius = float(doc["probe"].get("radius_mm", 8.0))
    eye, rays = pp.pixel_rays(cam, (h, w))
    out = {"normal": [], "ray": []}
    for fx, fy in points:
        x, y = min(int(fx * w), w - 1), min(int(fy * h), h - 1)
        one = np.zeros((h, w), dtype=bool)
        one[y, x] = True
        s = pp.surface_under(r, cam, one)[y, x]
        if not np.isfinite(s[0]):
            continue
        m = normal[y, x].astype(np.float64)
        m /= np.linalg.norm(m)
        centres = {"normal": s + (radius + hover_mm) * m,
                   "ray": along_ray(r, eye, rays[y, x], s, radius + hover_mm)}
        for how, c in centres.items():
            out[how].append(pp.core_offset_px(r, c, x, y))
    r.close()
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("scenes", nargs="*", help="scene names (default: every pointing walk's)")
    ap.add_argument("--hover-mm", type=float, default=1.0, help="h, the person's height (the window's start: 1 mm)")
    a = ap.parse_args()
    walks = os.path.join(REPO, "tests/window/walks/pointing")
    names = a.scenes or sorted(os.path.splitext(os.path.basename(p))[0] for p in glob.glob(os.path.join(walks, "*.walk")))
    print(f"| scene | points | along the normal: max / mean px | along the view ray: max / mean px |")
    print("| --- | --- | --- | --- |")
    for name in names:
        scene = scene_for(name)
        if scene is None:
            continue
        res = measure(scene, walk_points(os.path.join(walks, name + ".walk")), a.hover_mm)
        if res is None or not res["normal"]:
            continue
        n, v = np.array(res["normal"]), np.array(res["ray"])
        print(f"| {name} | {len(n)} | {n.max():.1f} / {n.mean():.1f} | {v.max():.1f} / {v.mean():.1f} |", flush=True)


if __name__ == "__main__":
    main()
