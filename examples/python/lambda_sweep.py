#!/usr/bin/env python3
"""Sweeps the Gabor wavelength λ of thesis Table 4.1 (a) and plots the texture's measured
spectrum peak against it (docs/api.md, "Python").

For each λ the scene's one material gets lambda_min = lambda_max = λ, the probe's contact disc
shows the texture over the centre of the orthographic 60 mm frame, and the texture AOV (the Gabor
value, before the speed modulation) is read as a numpy array. The peak is the power-weighted
centroid of the Hann-windowed spectrum along the texture's direction (θ = 0: along x), over
the half-plane that holds it (docs/gl-stack.md: the highest bin is many bins wide and useless).
A Gabor kernel's spectrum is a Gaussian centred on 1/λ, so the peak should follow 1/λ.

    PYTHONPATH=build/python python3 examples/python/lambda_sweep.py --out lambda_sweep.png
"""

import argparse
from pathlib import Path

import numpy as np

import pseudoshadow

SCENE = Path(__file__).resolve().parents[2] / "scenes" / "table4_1_a.toml"
FRAME_MM = 60.0       # the scene's ortho_height_mm: the image's side in mm
# A centred square inside the probe's 25 mm footprint, where the texture is evaluated
# (half-diagonal 22.6 mm).
CROP_MM = 32.0


def tolerance(lam):
    """Relative error allowed for one measured wavelength: three standard deviations of the
    centroid's scatter from a finite image, 0.36 / (periods across the crop) (docs/gl-stack.md):
    3.4 % at λ = 1 mm, 13.5 % at 4 mm. Fixed seed: the same numbers every run."""
    return 3.0 * 0.36 * lam / CROP_MM


def peak_frequency(texture, mm_per_pixel):
    """Spectrum peak along x of a square texture crop, cycles per mm."""
    n = texture.shape[0]
    window = np.outer(np.hanning(n), np.hanning(n))
    power = np.abs(np.fft.fft2((texture - texture.mean()) * window)) ** 2
    fx = np.fft.fftfreq(n, d=mm_per_pixel)[np.newaxis, :].repeat(n, axis=0)
    half = fx > 0  # the half-plane holding the peak (the other is its mirror image)
    return float((power[half] * fx[half]).sum() / power[half].sum())


def measure(lambdas, size=256, backend="auto", scene=SCENE):
    """The measured wavelength (1 / spectrum peak, mm) for each λ in mm."""
    renderer = pseudoshadow.Renderer(scene=scene, backend=backend,
                                     set={"render.size": [size, size]})
    mm_per_pixel = FRAME_MM / size
    crop = int(round(CROP_MM / mm_per_pixel))
    lo = (size - crop) // 2
    measured = []
    for lam in lambdas:
        renderer.set({"materials.table4_1_a.lambda_min": float(lam),
                      "materials.table4_1_a.lambda_max": float(lam)})
        frame = renderer.render(aovs=["texture"])
        texture = frame.aovs["texture"][lo:lo + crop, lo:lo + crop]
        measured.append(1.0 / peak_frequency(texture, mm_per_pixel))
    return measured


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="lambda_sweep.png", help="plot file (PNG)")
    parser.add_argument("--size", type=int, default=256, help="image side in pixels")
    parser.add_argument("--backend", default="auto", help="auto, egl or osmesa")
    args = parser.parse_args()

    lambdas = np.linspace(1.0, 4.0, 13)
    measured = measure(lambdas, size=args.size, backend=args.backend)
    for lam, got in zip(lambdas, measured):
        print(f"lambda {lam:.2f} mm  measured {got:.3f} mm  ({100 * (got / lam - 1):+.1f} %)")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5, 3.4), dpi=100)
    fine = np.linspace(lambdas[0], lambdas[-1], 200)
    ax.plot(fine, 1.0 / fine, color="0.6", label="1 / λ")
    ax.plot(lambdas, 1.0 / np.asarray(measured), "o", color="C0", label="measured peak")
    ax.set_xlabel("λ set in the scene (mm)")
    ax.set_ylabel("texture spectrum peak (cycles / mm)")
    ax.set_title("Table 4.1 (a): the texture follows λ", fontsize=10)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
