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
  - with --inside-navigation-box: where the ray through the pixel meets the scene's floor
    (--floor-z, the floor's top) with the probe's centre inside the [navigation] box's walls, less
    the probe's radius and --box-margin-mm (beyond a wall the pointer flies the view, by design);
  - with --outside-visual-stretch: where the ray through the pixel passes no surface drawn with a
    visual_stretch within the reach of its stretch (the drawn probe is moved off the hand there,
    by design: Illusion);
  - with --probe-fits: where the probe fits the surface under the pointer. The ray through the
    pixel is marched to the surface point S (pseudoshadow.Renderer.nearest_surface: the felt
    geometry), the probe is put --hover-mm above S along the drawn normal m there (its centre at
    S + (R + h) m), one frame is drawn, and its shadow's core must lie within --fit-px of the
    pixel. Where a hollow is narrower than the probe (Suzanne's eye sockets, the ear), or another
    part of the surface comes nearer (the brow over the eye, the cheek beside the nose), the place
    lies inside that part and the core elsewhere, by geometry, whatever the mapping does
    (docs/window.md);
  - with --charge-pull-below N: where the scene's [[fields]] charges pull the probe resting on
    the floor (--floor-z) by less than N newtons (their pull moves the drawn probe off the hand,
    by design: fields_bodies_demo);
  - with --raised: only where the drawn normal turns more than 25 degrees from the pointer
    plane's (the raised things on a floor: Poly's Suzanne);
  - away from every hidden surface (visible = false) by its radius, the probe's radius, its
    material's magnetic range and 5 mm, since a hidden magnet pulls the probe into contact by
    design; a sweep between two points that passes over that reach checks `unburied` only;
  - spread by farthest-point sampling from the qualifying pixel nearest the window's centre.
The points are the walk's inputs, not its expected outputs: the check (near=PX) measures the
shadow the window draws there.
"""
import argparse
import sys
import tomllib

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


def erode(mask, margin):
    """mask less every pixel within margin pixels (4-neighbourhood steps) of one outside it."""
    ok = mask.copy()
    for _ in range(margin):
        shifted = ok.copy()
        shifted[1:, :] &= ok[:-1, :]
        shifted[:-1, :] &= ok[1:, :]
        shifted[:, 1:] &= ok[:, :-1]
        shifted[:, :-1] &= ok[:, 1:]
        shifted[0, :] = shifted[-1, :] = False
        shifted[:, 0] = shifted[:, -1] = False
        ok = shifted
    return ok


def qualifying(normal, reference, min_facing, margin, max_crease_deg=None, also=None):
    """also(facing) -> mask: a further rule, applied before the margin is taken."""
    drawn = np.linalg.norm(normal, axis=2) > 0.5
    facing = drawn & (normal @ np.asarray(reference, dtype=np.float32) >= min_facing)
    if max_crease_deg is not None:
        facing &= smooth(normal, max_crease_deg)
    if also is not None:
        facing &= also(facing)
    ok = erode(facing, margin)
    ok[: READOUTS_BOX[1], : READOUTS_BOX[0]] = False
    ok[:EDGE, :] = ok[-EDGE:, :] = False
    ok[:, :EDGE] = ok[:, -EDGE:] = False
    return ok


def pixel_rays(camera, shape):
    """The eye and the ray through each pixel centre (perspective camera, world mm)."""
    h, w = shape
    eye = np.asarray(camera["position"], dtype=np.float64)
    forward = np.asarray(camera["target"], dtype=np.float64) - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, np.asarray(camera["up"], dtype=np.float64))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    if camera.get("projection", "perspective") != "perspective":
        sys.exit("pointing_points: --inside-navigation-box needs a perspective camera")
    tan_half = np.tan(np.radians(camera["fov_y_deg"]) / 2)
    ys, xs = np.mgrid[0:h, 0:w]
    u = ((xs + 0.5) / w * 2 - 1) * tan_half * w / h
    v = (1 - (ys + 0.5) / h * 2) * tan_half
    rays = forward + u[..., None] * right + v[..., None] * up
    return eye, rays / np.linalg.norm(rays, axis=2, keepdims=True)


def floor_points(camera, shape, floor_z):
    """Where the ray through each pixel centre meets the plane z = floor_z (NaN: it does not)."""
    eye, rays = pixel_rays(camera, shape)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (floor_z - eye[2]) / rays[..., 2]
    t[~(t > 0)] = np.nan
    return eye + t[..., None] * rays


def surface_under(renderer, camera, ok):
    """The felt surface point where each qualifying pixel's ray first meets the geometry (NaN:
    none within the camera's far plane), by sphere tracing on nearest_surface's distances."""
    eye, rays = pixel_rays(camera, ok.shape)
    dirs = rays[ok]
    t = np.full(len(dirs), float(camera.get("near_mm", 1.0)))
    far = float(camera.get("far_mm", 2000.0))
    live = np.ones(len(dirs), dtype=bool)
    met = np.zeros(len(dirs), dtype=bool)
    for _ in range(400):
        idx = np.nonzero(live)[0]
        if len(idx) == 0:
            break
        d, _, _ = renderer.nearest_surface(eye + t[idx, None] * dirs[idx], 1000.0)
        d = np.where(np.isfinite(d), d, 1000.0)
        hit = d < 0.005
        met[idx[hit]] = True
        t[idx] += d
        live[idx[hit | (t[idx] > far)]] = False
    points = np.full(ok.shape + (3,), np.nan)
    points[ok] = np.where(met[:, None], eye + t[:, None] * dirs, np.nan)
    return points


def core_centre(intensity):
    """The shadow's core as the window measures it (src/app/window/ui_layout.cpp, measure_shadow):
    the centroid of the pixels within 90 % of the darkest, in the box of the visible shadow
    (intensity > 1/255); pixel centres at i + 0.5. None: no shadow."""
    seen = intensity > 1.0 / 255.0
    if not seen.any():
        return None
    ys, xs = np.nonzero(seen)
    box = intensity[ys.min():ys.max() + 1, xs.min():xs.max() + 1]
    cy, cx = np.nonzero(box >= 0.9 * box.max())
    return xs.min() + cx.mean() + 0.5, ys.min() + cy.mean() + 0.5


def core_offset_px(renderer, centre, x, y):
    """Pixels from pixel (x, y)'s centre to the core of the shadow of the probe still at `centre`
    (one frame); inf where no shadow is drawn."""
    frame = renderer.render(probe=list(centre), velocity=[0.0, 0.0, 0.0], frames=1, aovs=["intensity"])
    core = core_centre(frame.aovs["intensity"])
    return np.inf if core is None else float(np.hypot(core[0] - (x + 0.5), core[1] - (y + 0.5)))


def probe_fits(scene, renderer, normal, facing, hover_mm, fit_px, step=3):
    """--probe-fits: pixels where the probe hovering hover_mm over the surface point S under it,
    along the drawn normal m there (centre S + (R + h) m, the place the pointer mapping aims for,
    docs/window.md "Over a slope"), draws its shadow's core within fit_px of the pixel. Tried on
    every step-th pixel of `facing` (one frame each), each answer standing for its step x step
    block."""
    doc = load(scene)
    radius = float(doc["probe"].get("radius_mm", 8.0))
    grid = np.zeros(facing.shape, dtype=bool)
    grid[step // 2::step, step // 2::step] = True
    tried = facing & grid
    s = surface_under(renderer, doc["camera"], tried)
    fits = np.zeros(facing.shape, dtype=bool)
    for y, x in zip(*np.nonzero(tried & np.isfinite(s[..., 0]))):
        m = normal[y, x].astype(np.float64)
        centre = s[y, x] + (radius + hover_mm) * m / np.linalg.norm(m)
        if core_offset_px(renderer, centre, x, y) <= fit_px:
            y0, x0 = y - step // 2, x - step // 2
            fits[max(y0, 0):y0 + step, max(x0, 0):x0 + step] = True
    return fits


def load(scene):
    with open(scene, "rb") as f:
        return tomllib.load(f)


def inside_box(scene, shape, floor_z, margin_mm):
    """Pixels whose floor point puts the probe's centre inside the navigation box's walls."""
    doc = load(scene)
    nav = doc.get("navigation")
    if nav is None:
        sys.exit(f"pointing_points: {scene} has no [navigation] box")
    centre = np.asarray(nav["box_center"], dtype=np.float64)
    half = np.asarray(nav["box_size_mm"], dtype=np.float64) / 2
    inset = doc["probe"]["radius_mm"] + margin_mm
    p = floor_points(doc["camera"], shape, floor_z)
    with np.errstate(invalid="ignore"):
        return (np.abs(p[..., 0] - centre[0]) <= half[0] - inset) & (np.abs(p[..., 1] - centre[1]) <= half[1] - inset)


def outside_stretch(scene, shape, floor_z):
    """Pixels whose probe hovers nowhere near a surface drawn with a visual_stretch: within its felt
    radius + the probe's radius + 10 mm (and a 20 mm fade) of its centre the drawn probe is
    stretched away from the hand, by design (src/render/world_markers.h, visual_position). Left out:
    rays that meet the drawn (stretched) sphere, and floor points whose hovering probe lies within
    that reach."""
    doc = load(scene)
    eye, rays = pixel_rays(doc["camera"], shape)
    radius = doc["probe"]["radius_mm"]
    centres = floor_points(doc["camera"], shape, floor_z + radius)
    ok = np.ones(shape, dtype=bool)
    for s in doc.get("surfaces", []):
        stretch = s.get("visual_stretch", [1.0, 1.0, 1.0])
        if list(stretch) == [1.0, 1.0, 1.0]:
            continue
        if s["type"] != "sphere":
            sys.exit("pointing_points: --outside-visual-stretch knows a stretched sphere only")
        centre = np.asarray(s["center"], dtype=np.float64)
        to_centre = centre - eye
        along = rays @ to_centre
        miss = np.linalg.norm(to_centre - along[..., None] * rays, axis=2)
        reach = s["radius_mm"] + radius + 10.0 + 20.0
        with np.errstate(invalid="ignore"):
            far = np.linalg.norm(centres - centre, axis=2) > reach
        ok &= (miss > s["radius_mm"] * max(stretch)) & far
    return ok


def material_range_mm(doc, name):
    """The magnetic pull's reach of a material (0 without one); materials of an included library
    are looked up in that library's file."""
    mats = dict(doc.get("materials", {}))
    return float(mats.get(name, {}).get("haptic", {}).get("magnetic_range_mm", 0.0))


def away_from_hidden(scene, shape, floor_z):
    """Pixels whose hovering probe stays out of the reach of every hidden surface (visible = false:
    felt, never drawn): its radius + the probe's radius + its material's magnetic range + 5 mm
    around its centre, the probe taken over the floor point of the pixel's ray (a hidden object
    lies on the floor; over a raised drawn surface the probe is on that surface, farther up). A
    hidden magnet pulls the probe into contact there by design, and nothing drawn tells the
    pointer it is there."""
    doc = load(scene)
    ok = np.ones(shape, dtype=bool)
    hidden = [s for s in doc.get("surfaces", []) if not s.get("visible", True)]
    if not hidden:
        return ok
    radius = doc["probe"]["radius_mm"]
    centres = floor_points(doc["camera"], shape, floor_z + radius)
    for s in hidden:
        if s["type"] != "sphere":
            sys.exit("pointing_points: a hidden surface other than a sphere is not known here")
        centre = np.asarray(s["center"], dtype=np.float64)
        reach = s["radius_mm"] + radius + library_range_mm(scene, doc, s.get("material", "")) + 5.0
        with np.errstate(invalid="ignore"):
            ok &= ~(np.linalg.norm(centres - centre, axis=2) <= reach)
    return ok


def weak_charge_pull(scene, shape, floor_z, max_pull_n):
    """--charge-pull-below N: pixels where every [[fields]] charge pulls the probe hovering over the
    floor point of the pixel's ray (its centre R above the floor's top: gravity rests it there) by
    less than N newtons, |q| r / (r^2 + s^2)^1.5 as the haptic loop's charge field
    (world/fields.cpp; s the softening, 2 mm unless the scene says). The pull moves the drawn probe off the hand by design: that is the scene's
    point (fields_bodies_demo)."""
    doc = load(scene)
    ok = np.ones(shape, dtype=bool)
    radius = doc["probe"]["radius_mm"]
    centres = floor_points(doc["camera"], shape, floor_z + radius)
    for f in doc.get("fields", []):
        if f.get("type") != "charge":
            continue
        r2 = np.sum((centres - np.asarray(f.get("position", [0.0, 0.0, 0.0]), dtype=np.float64)) ** 2, axis=2)
        soft2 = r2 + f.get("softening_mm", 2.0) ** 2
        with np.errstate(invalid="ignore"):
            ok &= abs(f["charge_n_mm2"]) * np.sqrt(r2) / soft2 ** 1.5 < max_pull_n
    return ok


def library_range_mm(scene, doc, name):
    """material_range_mm over the scene and the libraries it includes (the scene's own wins)."""
    import os
    found = material_range_mm(doc, name)
    if name in doc.get("materials", {}):
        return found
    for inc in doc.get("include", []):
        lib = load(os.path.join(os.path.dirname(scene), inc))
        if name in lib.get("materials", {}):
            return material_range_mm(lib, name)
    return found


def crosses(mask, a, b, samples=64):
    """Whether the straight pointer path from a to b (window fractions) passes a pixel off mask."""
    h, w = mask.shape
    for t in np.linspace(0.0, 1.0, samples):
        x = int(min(w - 1, (a[0] + t * (b[0] - a[0])) * w))
        y = int(min(h - 1, (a[1] + t * (b[1] - a[1])) * h))
        if not mask[y, x]:
            return True
    return False


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
    ap.add_argument("--inside-navigation-box", action="store_true",
                    help="only where the hovering probe stays inside the scene's [navigation] box")
    ap.add_argument("--floor-z", type=float, default=0.0, help="the floor's top, mm (--inside-navigation-box, --outside-visual-stretch)")
    ap.add_argument("--box-margin-mm", type=float, default=5.0,
                    help="mm inside the box's walls beyond the probe's radius (--inside-navigation-box)")
    ap.add_argument("--outside-visual-stretch", action="store_true",
                    help="only where the ray passes no surface drawn with a visual_stretch (Illusion)")
    ap.add_argument("--charge-pull-below", type=float, default=None, metavar="N",
                    help="only where the scene's charges pull the probe resting on the floor by less than N newtons")
    ap.add_argument("--raised", action="store_true",
                    help="only where the normal turns more than 25 degrees from the plane's (not the floor)")
    ap.add_argument("--probe-fits", action="store_true",
                    help="only where the probe placed ideally over the pointed point draws its shadow's core on it (Suzanne)")
    ap.add_argument("--hover-mm", type=float, default=1.0, help="the person's height h (the window's start, 1 mm)")
    ap.add_argument("--fit-px", type=float, default=3.0,
                    help="--probe-fits: how far from the pixel the ideally placed probe's shadow core may lie (half the walk's near)")
    ap.add_argument("--settle", type=float, default=0.0,
                    help="seconds to wait at each point before the rest check (a rolling view settles)")
    a = ap.parse_args()
    try:
        import pseudoshadow
    except ImportError:
        sys.exit("pointing_points: the Python module is not found: run with PYTHONPATH=build/python")
    renderer = pseudoshadow.Renderer(a.scene)
    frame = renderer.render(aovs=["normal"])
    reference = np.asarray(frame.stats["reference_normal"], dtype=np.float32)
    raised = frame.aovs["normal"] @ reference < np.cos(np.radians(25.0)) if a.raised else True

    def fits(facing):
        facing = facing & raised
        if a.probe_fits:
            facing &= probe_fits(a.scene, renderer, frame.aovs["normal"], facing, a.hover_mm, a.fit_px)
        return facing
    ok = qualifying(frame.aovs["normal"], frame.stats["reference_normal"], a.min_facing, a.margin, a.max_crease_deg,
                    also=fits)
    if a.inside_navigation_box:
        ok &= inside_box(a.scene, ok.shape, a.floor_z, a.box_margin_mm)
    if a.outside_visual_stretch:
        ok &= outside_stretch(a.scene, ok.shape, a.floor_z)
    if a.charge_pull_below is not None:
        ok &= weak_charge_pull(a.scene, ok.shape, a.floor_z, a.charge_pull_below)
    clear = away_from_hidden(a.scene, ok.shape, a.floor_z)
    ok &= clear
    points = spread(ok, a.count)
    if len(points) < a.count:
        sys.exit(f"pointing_points: only {len(points)} qualifying points in {a.scene}")
    crease = f" --max-crease-deg {a.max_crease_deg:g}" if a.max_crease_deg is not None else ""
    check = f" --check {a.check}" if a.check != "free" else ""
    if a.settle > 0:
        crease += f" --settle {a.settle:g}"
    if a.outside_visual_stretch:
        crease += f" --outside-visual-stretch --floor-z {a.floor_z:g}"
    if a.charge_pull_below is not None:
        crease += f" --charge-pull-below {a.charge_pull_below:g} --floor-z {a.floor_z:g}"
    if a.raised:
        crease += " --raised"
    if a.probe_fits:
        crease += f" --probe-fits --hover-mm {a.hover_mm:g} --fit-px {a.fit_px:g}"
    if a.inside_navigation_box:
        crease += f" --inside-navigation-box --floor-z {a.floor_z:g} --box-margin-mm {a.box_margin_mm:g}"
    count = f"--count {a.count} " if a.count != 8 else ""
    print(f"# {a.count} points over the visible surfaces (tools/pointing_points.py {count}--margin {a.margin} "
          f"--min-facing {a.min_facing:g}{crease}{check})")
    # From the window's centre (where the walks rest the pointer first), point to point as a hand
    # moves a mouse, in 0.5 s: a jump across the window in one reading sends the hand's filter
    # swinging out of reach for ~2 s before it settles.
    at = (0.5, 0.5)
    # A sweep over a hidden surface's reach checks only that the proxy is never buried: the pull
    # of a hidden magnet may bring the probe into contact there, by design.
    for x, y in points:
        check = a.check
        if crosses(clear, at, (x, y)):
            check = "unburied"
            print("# over a hidden surface's reach (felt, not drawn): contact allowed, burial not")
        print(f"sweep {at[0]:.3f} {at[1]:.3f} {x:.3f} {y:.3f} 0.5 {check}")
        if a.settle > 0:
            print(f"wait {a.settle:g} {a.check}")
        print(f"wait 1.5 {a.check} still near={a.near:g}")
        at = (x, y)


if __name__ == "__main__":
    main()
