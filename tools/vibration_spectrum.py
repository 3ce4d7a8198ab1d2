#!/usr/bin/env python3
"""The spectral peak of a vibration WAV (`pseudoshadow replay --vibration`) over a time window.

usage: tools/vibration_spectrum.py FILE.wav T0 T1 [PLOT.png]

Welch's power spectrum (Hann, 8192-sample segments, half overlapping) of the samples in
[T0, T1) seconds, and its peak: a parabola fitted to log power over the bins around the largest
that hold at least a third of it (the estimator of tests/vibration/stroke.h). Prints the peak in
Hz; with PLOT.png also draws the spectrum (matplotlib).
"""
import sys
import wave

import numpy as np


def read(path):
    with wave.open(path, "rb") as w:
        assert w.getsampwidth() == 2 and w.getnchannels() == 1, "expects 16-bit mono"
        rate = w.getframerate()
        x = np.frombuffer(w.readframes(w.getnframes()), dtype="<i2").astype(float) / 32767.0
    return x, rate


def welch(x, n=8192):
    win = 0.5 * (1.0 - np.cos(2.0 * np.pi * np.arange(n) / n))
    segs = [x[s:s + n] * win for s in range(0, len(x) - n + 1, n // 2)]
    if not segs:
        raise SystemExit("window shorter than one 8192-sample segment")
    return np.mean([np.abs(np.fft.rfft(s)) ** 2 for s in segs], axis=0)


def peak(psd, bin_hz):
    top = int(np.argmax(psd[1:])) + 1
    lo, hi = top, top
    while lo > 1 and psd[lo - 1] >= psd[top] / 3.0:
        lo -= 1
    while hi + 1 < len(psd) and psd[hi + 1] >= psd[top] / 3.0:
        hi += 1
    if hi - lo < 2:
        return top * bin_hz
    k = np.arange(lo, hi + 1) - top
    c2, c1, _ = np.polyfit(k, np.log(psd[lo:hi + 1]), 2)
    return (top - c1 / (2.0 * c2)) * bin_hz if c2 < 0 else top * bin_hz


def main():
    if len(sys.argv) not in (4, 5):
        raise SystemExit(__doc__)
    x, rate = read(sys.argv[1])
    t0, t1 = float(sys.argv[2]), float(sys.argv[3])
    psd = welch(x[int(t0 * rate):int(t1 * rate)])
    bin_hz = rate / 8192.0
    print(f"{sys.argv[1]}: [{t0}, {t1}) s, rms {np.sqrt(np.mean(x[int(t0 * rate):int(t1 * rate)] ** 2)):.4f}, "
          f"spectral peak {peak(psd, bin_hz):.2f} Hz")
    if len(sys.argv) == 5:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        f = np.arange(len(psd)) * bin_hz
        plt.figure(figsize=(6, 3))
        plt.semilogy(f, psd)
        plt.xlim(0, 400)
        plt.xlabel("Hz")
        plt.ylabel("power")
        plt.tight_layout()
        plt.savefig(sys.argv[4], dpi=100)


if __name__ == "__main__":
    main()
