#!/usr/bin/python3
"""The figures behind shaders/bsdf/anisotropy.h's diffuse coupling (numpy; Debian: python3-numpy).

bsdf.h bounds the dielectric layer's directional albedo by E(mu) = F0 + (1 - F0) K(mu, r),
K = kappa(r) (1 - mu)^n(r), fitted over isotropic roughness r. With F0 = 0 (the tightest case:
F0 E0 + (1 - F0) S <= F0 + (1 - F0) K whenever S <= K, E0 <= 1) the bound needs the Schlick
part of the layer's albedo, S(mu, phi) = mean over visible normals h of (1 - wo.h)^5 G2 / G1,
to stay below K. This script measures max(S - K) for the anisotropic lobe (alpha_t =
mix(r^2, 1, s^2), alpha_b = r^2) with K taken at a coupling roughness, for the rules compared:
  r                the isotropic roughness (alpha_b's): excess up to ~0.09 at grazing angles
  r (1 - s^2 / 4)  what bsdf.h uses: excess ~0.0008, as the isotropic fit's own (~0.001)

Usage: anisotropy_coupling_bound.py [SAMPLES]   (default 300000 visible normals a point;
about a minute per rule on one core)
"""
import sys

import numpy as np

SAMPLES = int(sys.argv[1]) if len(sys.argv) > 1 else 300000
rng = np.random.default_rng(1)


def stretched(w, ax, ay):  # |cos| (1 + 2 Lambda)
    return np.sqrt(w[..., 2] ** 2 + ax * ax * w[..., 0] ** 2 + ay * ay * w[..., 1] ** 2)


def visible_normals(wo, ax, ay, n):  # microfacet.h's spherical caps, stretched
    ws = np.array([wo[0] * ax, wo[1] * ay, wo[2]])
    ws /= np.linalg.norm(ws)
    phi = 2 * np.pi * rng.random(n)
    z = (1 - rng.random(n)) * (1 + ws[2]) - ws[2]
    s = np.sqrt(np.clip(1 - z * z, 0, 1))
    h = np.stack([(s * np.cos(phi) + ws[0]) * ax, (s * np.sin(phi) + ws[1]) * ay,
                  np.maximum(z + ws[2], 0)], -1)
    return h / np.linalg.norm(h, axis=1, keepdims=True)


def schlick_albedo(mu, phi, ax, ay):
    wo = np.array([np.sqrt(1 - mu * mu) * np.cos(phi), np.sqrt(1 - mu * mu) * np.sin(phi), mu])
    h = visible_normals(wo, ax, ay, SAMPLES)
    c = h @ wo
    wi = 2 * c[:, None] * h - wo
    lo = stretched(wo, ax, ay) / mu  # 1 + 2 Lambda(wo)
    li = stretched(wi, ax, ay) / np.maximum(np.abs(wi[:, 2]), 1e-30)
    g2_over_g1 = np.where(wi[:, 2] > 0, (1 + lo) / (lo + li), 0)  # (1 + L_o) / (1 + L_o + L_i)
    return np.mean(g2_over_g1 * (1 - c) ** 5)


def bound(mu, r):
    kappa = 1 / (1 + 20.7 * r ** 2.32)
    return kappa * (1 - mu) ** (2.84 + 5.15 * (r - 0.44) ** 2)


RULES = {"r": lambda r, s: r, "r (1 - s^2 / 4)": lambda r, s: r * (1 - 0.25 * s * s)}
for name, rule in RULES.items():
    worst = (-1.0,)
    for r in np.linspace(0, 1, 11):
        for s in [0.0, 0.2, 0.4, 0.6, 0.8, 1.0]:
            a = r * r
            ax, ay = max(a + (1 - a) * s * s, 1e-4), max(a, 1e-4)
            for mu in [0.005, 0.02, 0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.9]:
                for phi in np.linspace(0, np.pi / 2, 5):
                    excess = schlick_albedo(mu, phi, ax, ay) - bound(mu, rule(r, s))
                    if excess > worst[0]:
                        worst = (excess, r, s, mu, phi)
    print("coupling roughness %-16s largest excess %.4f at r %.1f, s %.1f, mu %.3f, phi %.2f"
          % ((name,) + tuple(worst)))
