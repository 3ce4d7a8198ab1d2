#!/usr/bin/python3
"""Plots a replay's sound track with its events marked (docs/sound.md).

usage: tools/plot_sound.py SOUND.wav EVENTS.jsonl OUT.png

Top: the whole track, a line at each event's time. Below: the first 30 ms after each of the
first four events (the click itself), and the loudness curves of contact clicks and body
impacts (the SynthParams defaults, src/audio/synth.h)."""
import json
import sys
import wave

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(wav_path, events_path, out_path):
    with wave.open(wav_path) as w:
        rate = w.getframerate()
        x = np.frombuffer(w.readframes(w.getnframes()), dtype="<i2") / 32767.0
    with open(events_path) as f:
        events = [json.loads(line) for line in f if line.strip()]
    t = np.arange(len(x)) / rate
    zooms = events[:4]
    fig = plt.figure(figsize=(10, 6.5), constrained_layout=True)
    grid = fig.add_gridspec(2, max(2, len(zooms) + 1))
    top = fig.add_subplot(grid[0, :])
    top.plot(t, x, lw=0.6, color="k")
    for e in events:
        top.axvline(e["t"], color="tab:red", lw=0.8, ls="--")
        top.annotate(f'{e["event"]}\nt={e["t"]:.3f} s', (e["t"], 0.95), xycoords=("data", "axes fraction"),
                     fontsize=8, va="top", ha="left", color="tab:red")
    top.set(xlabel="time (s)", ylabel="amplitude (full scale 1)", xlim=(0, t[-1]),
            title=f"{wav_path.split('/')[-1]}: {len(x)} samples at {rate} Hz, {len(events)} events")
    for i, e in enumerate(zooms):
        ax = fig.add_subplot(grid[1, i])
        s = round(e["t"] * rate)
        seg = slice(max(0, s - rate // 500), min(len(x), s + 3 * rate // 100))
        ax.plot((np.arange(len(x))[seg] - s) * 1000.0 / rate, x[seg], lw=0.7, color="k")
        ax.axvline(0, color="tab:red", lw=0.8, ls="--")
        ax.set(title=f'{e["event"]} (tick {e["tick"]})', xlabel="ms after the event")
    ax = fig.add_subplot(grid[1, len(zooms)])
    v = np.linspace(0, 1500, 300)
    ax.plot(v, 0.9 * (1 - np.exp(-v / 300)), label="body impact")
    ax.plot(v, 0.1 + 0.5 * (1 - np.exp(-v / 60)), label="contact click")
    ax.set(title="peak vs speed", xlabel="speed (mm/s)", ylim=(0, 1))
    ax.legend(fontsize=8)
    fig.savefig(out_path, dpi=90)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__.strip().splitlines()[2])
    main(*sys.argv[1:])
