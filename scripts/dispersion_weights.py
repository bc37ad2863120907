#!/usr/bin/env python3
"""The per-wavelength RGB weights of KHR_materials_dispersion (shaders/bsdf/dispersion.h).

A path that meets dispersive glass picks one wavelength, uniform over [380, 780] nm, and
multiplies its RGB throughput by w(lambda): the CIE 1931 2-degree colour matching functions
(Wyman, Sloan and Shirley 2013's multi-lobe Gaussian fit, JCGT 2(2)) taken to linear sRGB
(D65 matrix), negative parts clipped to 0, each channel scaled so that its average over the
range is 1. A flat (white) spectrum then gives RGB (1, 1, 1) on average, exactly.

Prints the three scale factors dispersion.h holds, from a fine midpoint quadrature of the same
functions; tests/unit/test_dispersion.cpp checks the average again in C++.
"""
import math

LAMBDA_MIN, LAMBDA_MAX = 380.0, 780.0


def lobe(x, mu, s1, s2):
    t = (x - mu) / (s1 if x < mu else s2)
    return math.exp(-0.5 * t * t)


def xyz(l):
    x = (1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7)
         - 0.065 * lobe(l, 501.1, 20.4, 26.2))
    y = 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1)
    z = 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8)
    return x, y, z


def rgb(l):
    x, y, z = xyz(l)
    r = 3.2404542 * x - 1.5371385 * y - 0.4985314 * z
    g = -0.9692660 * x + 1.8760108 * y + 0.0415560 * z
    b = 0.0556434 * x - 0.2040259 * y + 1.0572252 * z
    return max(r, 0.0), max(g, 0.0), max(b, 0.0)


def main():
    n = 400000
    h = (LAMBDA_MAX - LAMBDA_MIN) / n
    sums = [0.0, 0.0, 0.0]
    for i in range(n):
        c = rgb(LAMBDA_MIN + (i + 0.5) * h)
        for k in range(3):
            sums[k] += c[k]
    for name, s in zip("RGB", sums):
        print(f"#define WF_DISPERSION_SCALE_{name} {n / s:.7f}f")


if __name__ == "__main__":
    main()
