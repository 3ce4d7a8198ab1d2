#!/usr/bin/env python3
"""Where a pointing walk rests the pointer: N points spread over a scene's visible surfaces.

    PYTHONPATH=build/python tools/pointing_points.py SCENE.toml [--count 8] [--margin 14]

Renders the scene's first frame through the Python module (the CLI's first frame) with the
`normal` AOV and prints walk lines (`move X Y` / `wait ... near=6`) for tests/window/walks/.
The rule, so the points are chosen without looking at where the shadow lands:
  - a pixel qualifies where a surface is drawn (a non-zero normal) that faces the pointer's plane
    (normal . reference normal >= --min-facing, 0.5: up to 60 degrees of slope; a wall seen
    edge-on from the plane's normal cannot carry a shadow under the pointer, docs/window.md);
  - with --max-crease-deg D: not where the normal turns by more than D degrees from one pixel to
    the next (a crease, or where the sheets of a surface embedded in 4D cross: no one surface is
    under the pointer there, and the shadow shows on the probe's sheet only, docs/fourd.md);
  - at least --margin pixels from any pixel that does not (silhouettes, steep walls, the sky,
    creases), so a hand's pixel of jitter does not fall off an edge;
  - outside the readouts box (top left) where the window draws over the image, and 64 px from
    the window's edges (a shadow cut there has its centre pulled inwards);
  - spread by farthest-point sampling from the qualifying pixel nearest the window's centre.
The points are the walk's inputs, not its expected outputs: the check (near=PX) measures the
shadow the window draws there.
"""
import argparse
import sys

import numpy as np

# The readouts box of the window (src/app/window/hud.cpp) at its widest, window pixels: the
# pointer over it still points at the scene, but the box hides the shadow drawn there.
READOUTS_BOX = (300, 210)
# Window pixels from the window's edges: a shadow cut by the edge has its centre pulled inwards.
EDGE = 64


def smooth(normal, max_crease_deg):
    """Pixels whose normal turns by at most max_crease_deg to each 4-neighbour."""
    cos_max = np.cos(np.radians(max_crease_deg))
    ok = np.ones(normal.shape[:2], dtype=bool)
    across = np.sum(normal[1:, :] * normal[:-1, :], axis=2) >= cos_max
    ok[1:, :] &= across
    ok[:-1, :] &= across
    along = np.sum(normal[:, 1:] * normal[:, :-1], axis=2) >= cos_max
    ok[:, 1:] &= along
    ok[:, :-1] &= along
    return ok


def qualifying(normal, reference, min_facing, margin, max_crease_deg=None):
    drawn = np.linalg.norm(normal, axis=2) > 0.5
    facing = drawn & (normal @ np.asarray(reference, dtype=np.float32) >= min_facing)
    if max_crease_deg is not None:
        facing &= smooth(normal, max_crease_deg)
    ok = facing.copy()
    for _ in range(margin):  # erosion by one pixel, margin times (4-neighbourhood)
        shifted = ok.copy()
        shifted[1:, :] &= ok[:-1, :]
        shifted[:-1, :] &= ok[1:, :]
        shifted[:, 1:] &= ok[:, :-1]
        shifted[:, :-1] &= ok[:, 1:]
        shifted[0, :] = shifted[-1, :] = False
        shifted[:, 0] = shifted[:, -1] = False
        ok = shifted
    ok[: READOUTS_BOX[1], : READOUTS_BOX[0]] = False
    ok[:EDGE, :] = ok[-EDGE:, :] = False
    ok[:, :EDGE] = ok[:, -EDGE:] = False
    return ok


def spread(ok, count):
    ys, xs = np.nonzero(ok)
    if len(xs) == 0:
        return []
    h, w = ok.shape
    pts = np.stack([xs + 0.5, ys + 0.5], axis=1)
    first = int(np.argmin(np.hypot(pts[:, 0] - w / 2, pts[:, 1] - h / 2)))
    chosen = [first]
    dist = np.hypot(pts[:, 0] - pts[first, 0], pts[:, 1] - pts[first, 1])
    while len(chosen) < min(count, len(pts)):
        nxt = int(np.argmax(dist))
        chosen.append(nxt)
        dist = np.minimum(dist, np.hypot(pts[:, 0] - pts[nxt, 0], pts[:, 1] - pts[nxt, 1]))
    return [(pts[i, 0] / w, pts[i, 1] / h) for i in chosen]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene")
    ap.add_argument("--count", type=int, default=8)
    ap.add_argument("--margin", type=int, default=14, help="pixels from any edge of the qualifying area")
    ap.add_argument("--min-facing", type=float, default=0.5)
    ap.add_argument("--near", type=float, default=6.0, help="the walk's tolerance, window pixels")
    ap.add_argument("--max-crease-deg", type=float, default=None,
                    help="leave out pixels where the normal turns by more than this to a neighbour")
    ap.add_argument("--check", default="free", choices=["free", "sheets"],
                    help="the walk's check while the pointer moves (sheets: a surface embedded in 4D)")
    a = ap.parse_args()
    try:
        import pseudoshadow
    except ImportError:
        sys.exit("pointing_points: the Python module is not found: run with PYTHONPATH=build/python")
    frame = pseudoshadow.Renderer(a.scene).render(aovs=["normal"])
    ok = qualifying(frame.aovs["normal"], frame.stats["reference_normal"], a.min_facing, a.margin, a.max_crease_deg)
    points = spread(ok, a.count)
    if len(points) < a.count:
        sys.exit(f"pointing_points: only {len(points)} qualifying points in {a.scene}")
    crease = f" --max-crease-deg {a.max_crease_deg:g}" if a.max_crease_deg is not None else ""
    check = f" --check {a.check}" if a.check != "free" else ""
    print(f"# {a.count} points over the visible surfaces (tools/pointing_points.py --margin {a.margin} "
          f"--min-facing {a.min_facing:g}{crease}{check})")
    # From the window's centre (where the walks rest the pointer first), point to point as a hand
    # moves a mouse, in 0.5 s: a jump across the window in one reading sends the hand's filter
    # swinging out of reach for ~2 s before it settles.
    at = (0.5, 0.5)
    for x, y in points:
        print(f"sweep {at[0]:.3f} {at[1]:.3f} {x:.3f} {y:.3f} 0.5 {a.check}")
        print(f"wait 1.5 {a.check} still near={a.near:g}")
        at = (x, y)


if __name__ == "__main__":
    main()
