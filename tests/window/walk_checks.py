"""The walk's checks (walk.py): each step's frames from the window's `--readouts-log`, and after
the window closed, its `--ui-report` and the override files its S taps saved. Each returns
failure messages. Standard library only."""
import json
import os

# Penetration a hovering frame may show, mm: the frame's largest penetration is measured on the
# render mesh while the hand hovers 1 mm over the haptic geometry (the same triangles for meshes,
# tessellated analytic shapes otherwise: a sphere's 64-segment mesh lies up to ~0.2 mm inside
# the true sphere of the larger scenes), so 0.25 mm, a quarter of the hover height.
PENETRATION_TOL_MM = 0.25
# View drift allowed while the pointer rests, mm: a resting view does not move at all; 0.5 mm
# is under one pixel of every shipped scene's camera.
DRIFT_TOL_MM = 0.5
# The same for the turn a rolling 4D surface gives the view (view_turn_deg), degrees: 0.1 degree
# moves the rolling flat torus's camera target (150 mm away) by 0.26 mm, inside DRIFT_TOL_MM.
# Logs written before the field existed read as unturned.
TURN_TOL_DEG = 0.1
# Depth a hovering hand may graze a surface, mm: the mouse is read once a frame (4-30 frames a
# second on llvmpipe) and the hand's filter coasts between readings, on a straight line that cuts
# under a curved surface the pointer sweeps over; half the 1 mm hover height.
CONTACT_TOL_MM = 0.5
# The proxy's depth inside the haptic geometry, mm: the god-object keeps it out up to its contact
# epsilon (1e-3 mm); 0.05 mm leaves room for the float read-back of the log's 4 decimals.
BURIED_TOL_MM = 0.05


# The readouts log's times have 4 decimals and the event log's all of them: 0.1 ms apart at most
# for the same tick, a tenth of the 1 ms between two ticks, so the tick before still fails.
LOG_TIME_TOL_S = 1e-4


def check_near(step, frame, where, report):
    """near=PX: on the step's last frame the pseudo-shadow's centre (shadow_px, the --ui-report
    measure) is within PX window pixels of the pointer (pointer_px)."""
    pointer, shadow = frame.get("pointer_px"), frame.get("shadow_px")
    if pointer is None or shadow is None:
        return [f"{where}: frame {frame['frame']} has no {'pointer' if pointer is None else 'shadow'} on screen"]
    d = ((pointer[0] - shadow[0]) ** 2 + (pointer[1] - shadow[1]) ** 2) ** 0.5
    report["max_pointer_shadow_px"] = max(report.get("max_pointer_shadow_px", 0.0), d)
    if d > step["near"]:
        return [f"{where}: the shadow's centre {shadow} is {d:.1f} px from the pointer {pointer} at frame "
                f"{frame['frame']} (at most {step['near']:g})"]
    return []


def new_report():
    """The largest values check_step() has seen, all 0 before the first step (walk.py prints them)."""
    return {"max_rest_penetration_mm": 0.0, "max_sweep_penetration_mm": 0.0, "max_hover_pressed_mm": 0.0,
            "max_hover_buried_mm": 0.0, "max_rest_drift_mm": 0.0}


def check_step(step, frames, report):
    """The step's checks on its frames; returns failure messages."""
    where = f"walk line {step['line']} ({step['op']})"
    out = []
    if not frames:
        return [f"{where}: no frame drawn during the step"] if (step["free"] or step["still"] or step["expect"]) else []
    if step["free"] or step["unburied"] or step["sheets"]:
        for f in frames:
            key = "max_rest_penetration_mm" if step["still"] else "max_sweep_penetration_mm"
            if not f["contact"]:
                report[key] = max(report[key], f["penetration_mm"])
            report["max_hover_buried_mm"] = max(report["max_hover_buried_mm"], f["buried_mm"])
            # What the hand pushed in: the surface's hold (held_mm), without a field's push. In
            # Field a repelling charge pushes the proxy hovering 1 mm under it onto the floor,
            # pressed 1.1 mm from the hand, held 0.1-0.3 mm (the hand's filter lag): the field's
            # touch, not the pointer's. Logs written before held_mm existed read pressed_mm.
            held = f.get("held_mm", f["pressed_mm"])
            if f["contact"]:
                report["max_hover_pressed_mm"] = max(report["max_hover_pressed_mm"], held)
            touching = step["free"] and f["contact"] and held > CONTACT_TOL_MM
            # The drawn probe's penetration counts while the pointer rests and the proxy touches
            # nothing. It is measured per pixel along the renderer's reference normal, which
            # converges away from the pointer's plane after the start: a probe passing beside a steep
            # surface (materials_demo's ball) reads as up to ~27 mm inside it for a frame. The
            # proxy's own depth (buried_mm) counts on every frame.
            drawn_in = step["still"] and not f["contact"] and f["penetration_mm"] > PENETRATION_TOL_MM
            # A surface embedded in 4D is touched sheet by sheet: the proxy passes through the others
            # by design (docs/fourd.md), so its overlap with them is no burial.
            buried = not step["sheets"] and f["buried_mm"] > BURIED_TOL_MM
            if touching or drawn_in or buried:
                out.append(f"{where}: frame {f['frame']} buried or in contact while only the pointer moved: "
                           f"state {f['state']}, pressed {f['pressed_mm']} mm, penetration {f['penetration_mm']} mm, "
                           f"proxy buried {f['buried_mm']} mm, force {f['force_n']} N")
                break
    if step["still"]:
        rest = frames[len(frames) // 3:]  # the first third: the view settles after the last motion
        a, b = rest[0]["view_offset_mm"], rest[-1]["view_offset_mm"]
        drift = sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5
        report["max_rest_drift_mm"] = max(report["max_rest_drift_mm"], drift)
        if drift > DRIFT_TOL_MM:
            out.append(f"{where}: the view drifted {drift:.2f} mm while the pointer rested")
        # The turn's angle alone: a view turning on at rest changes it (a turn that kept its angle
        # while changing its axis would pass; no rolling view does that at rest).
        turned = abs(rest[-1].get("view_turn_deg", 0.0) - rest[0].get("view_turn_deg", 0.0))
        if turned > TURN_TOL_DEG:
            out.append(f"{where}: the view turned {turned:.2f} degrees while the pointer rested")
    if step["scene"] is not None and os.path.basename(frames[-1]["scene"]) != step["scene"]:
        out.append(f"{where}: scene {frames[-1]['scene']} at frame {frames[-1]['frame']}, expected {step['scene']}")
    if step["switches"] is not None:
        names = [f["scene"] for f in frames]
        switches = sum(1 for a, b in zip(names, names[1:]) if a != b)
        report["switches"] = report.get("switches", 0) + switches
        if switches and step["op"] == "key":  # key presses the window handled up to the switch
            first = next(i for i in range(1, len(names)) if names[i] != names[i - 1])
            report.setdefault("presses_to_switch", []).append(sum(f["keys"] for f in frames[1:first + 1]))
        if switches != step["switches"]:
            out.append(f"{where}: {switches} scene switches ({' -> '.join(dict.fromkeys(names))}), expected {step['switches']}")
    if step["home"]:
        off = sum(x * x for x in frames[-1]["view_offset_mm"]) ** 0.5
        if off > DRIFT_TOL_MM:
            out.append(f"{where}: the view is {off:.2f} mm from home at frame {frames[-1]['frame']}")
        turn = frames[-1].get("view_turn_deg", 0.0)
        if turn > TURN_TOL_DEG:
            out.append(f"{where}: the view is turned {turn:.2f} degrees from home at frame {frames[-1]['frame']}")
    if step["dent_min"] is not None:
        deepest = max((f.get("dent_mm") or 0.0) for f in frames)
        report["max_dent_mm"] = max(report.get("max_dent_mm", 0.0), deepest)
        if deepest < step["dent_min"]:
            out.append(f"{where}: the deepest dent was {deepest:.2f} mm, expected at least {step['dent_min']} mm")
    if step["dent_max"] is not None and (frames[-1].get("dent_mm") or 0.0) > step["dent_max"]:
        out.append(f"{where}: still dented {frames[-1]['dent_mm']:.2f} mm at frame {frames[-1]['frame']}, "
                   f"expected at most {step['dent_max']} mm")
    if step["near"] is not None:
        out += check_near(step, frames[-1], where, report)
    if step["expect"]:
        state = frames[-1]["state"].replace(" ", "_")
        if state not in step["expect"]:
            out.append(f"{where}: state {state} at frame {frames[-1]['frame']}, expected {'|'.join(sorted(step['expect']))}")
    return out


def read_events(out_dir):
    """The window's --events log (one JSON object a line), [] when it wrote none."""
    path = os.path.join(out_dir, "events.jsonl")
    if not os.path.exists(path):
        return []
    with open(path, encoding="utf-8") as f:
        return [json.loads(line) for line in f if line.strip()]


def check_fired(events, fired_steps, report):
    """After the window closed: each `fired=N` step saw exactly N button_fired events from its start
    to 1 s after its end (a press the step's last key made fires within a few frames)."""
    out = []
    for step, t0, t1 in fired_steps:
        n = sum(1 for e in events if e["event"] == "button_fired" and t0 <= e["t"] <= t1 + 1.0)
        report.setdefault("buttons_fired", []).append(n)
        if n != step["fired"]:
            out.append(f"walk line {step['line']} ({step['op']}): {n} button_fired events, expected {step['fired']}")
    return out


def check_switch_frames(frames, events, report):
    """After the window closed, on every walk: the first frame of each world switched to draws the
    state of the tick that adopted it (its t_s at or after that scene_switched event) or a later
    one, so it shows the probe placed in the new world: neither the proxy buried nor the drawn
    probe penetrating (the hover tolerances), and not the old world's press."""
    out = []
    switched = [e for e in events if e["event"] == "scene_switched"]
    for before, first in zip(frames, frames[1:]):
        if os.path.basename(before["scene"]) == os.path.basename(first["scene"]):
            continue
        name = os.path.basename(first["scene"])
        adopted = next((e for e in switched if e["t"] > before["t_s"] and os.path.basename(e["label"]) == name), None)
        report["switch_frames_checked"] = report.get("switch_frames_checked", 0) + 1
        where = f"frame {first['frame']}, the first of {name}"
        if adopted is None:
            out.append(f"{where}: no scene_switched event to {name} after frame {before['frame']}")
        elif first["t_s"] < adopted["t"] - LOG_TIME_TOL_S:
            out.append(f"{where}: drawn from the state at {first['t_s']} s, before the switch's tick at "
                       f"{adopted['t']:.4f} s (state {first['state']}, button {first['button']})")
        elif first["buried_mm"] > BURIED_TOL_MM or first["penetration_mm"] > PENETRATION_TOL_MM:
            out.append(f"{where}: proxy buried {first['buried_mm']} mm, drawn penetration {first['penetration_mm']} mm")
    return out


def same_buttons(a, b, tol_px=0.5):
    """Two frames' button rectangles (--ui-report) are the same buttons at the same places."""
    return len(a) == len(b) and all(abs(x - y) <= tol_px for ra, rb in zip(a, b) for x, y in zip(ra, rb))


def check_panel(out_dir, still_steps, report):
    """After the window closed: the panel's rectangle (--ui-report, by frame) on every frame of
    each panel_still step is shown and the same - it does not jump away from the pointer; the
    first_buttons steps' last frame shows the buttons of the walk's first frame, at their places
    (within 0.5 px: the rectangles are projected plates, the same camera gives the same bits)."""
    if not still_steps:
        return []
    with open(os.path.join(out_dir, "ui.json"), encoding="utf-8") as f:
        ui = {fr["frame"]: fr for fr in json.load(f)["frames"]}
    out = []
    first = ui[min(ui)]["buttons"] if ui else []
    for step, frames in still_steps:
        where = f"walk line {step['line']} ({step['op']})"
        if step["first_buttons"]:
            last = [ui[n]["buttons"] for n in frames if n in ui]
            if not last or not same_buttons(last[-1], first):
                out.append(f"{where}: the buttons {last[-1] if last else 'of no frame'} are not the first frame's {first}")
            if not step["panel_still"]:
                continue
        rects = [ui[n]["panel"] for n in frames if n in ui]
        report["panel_frames_checked"] = report.get("panel_frames_checked", 0) + len(rects)
        if not rects or any(r is None for r in rects):
            out.append(f"{where}: the panel is not shown on every frame of the step")
        elif len({tuple(r) for r in rects}) > 1:
            out.append(f"{where}: the panel moved while the pointer came to it: {rects[0]} -> "
                       f"{next(r for r in rects if r != rects[0])}")
    return out


def check_saves(out_dir, saves):
    """After the window closed: each checked `save` step's override file (the panel's edits as
    `run` saved them beside the screenshot) keeps every min <= max pair and holds the edited key."""
    out = []
    for step, index in saves:
        where = f"walk line {step['line']} (save)"
        path = os.path.join(out_dir, f"screenshot_{index:04d}.overrides.toml")
        if not os.path.exists(path):
            out.append(f"{where}: no {os.path.basename(path)}: the S tap saved nothing")
            continue
        values = {}
        with open(path, encoding="utf-8") as f:
            for line in f:
                if "=" in line and not line.lstrip().startswith("#"):
                    k, v = (x.strip() for x in line.split("=", 1))
                    values[k] = v
        if step["edited"] and not any(k.endswith(step["edited"]) for k in values):
            out.append(f"{where}: the panel's edit of {step['edited']} is not in {os.path.basename(path)}")
        for k, v in values.items():
            if step["valid"] and k.endswith("_min") and k[:-4] + "_max" in values:
                lo, hi = float(v), float(values[k[:-4] + "_max"])
                if lo > hi:
                    out.append(f"{where}: {k} = {lo} > {k[:-4]}_max = {hi}: the panel broke an invariant")
    return out
