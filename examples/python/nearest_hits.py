# SPDX-License-Identifier: Apache-2.0
"""A batch of rays against a torus: the nearest hits and their unit normals.

Run: PYTHONPATH=build/python python3 examples/python/nearest_hits.py
"""
import numpy as np

import toroid

# The torus in object space: ring in the xy-plane, axis z, centred at 0.
major, minor = 1.0, 0.25

# Seven rays from an eye above and in front, aimed at points of the x axis:
# some hit the near side of the tube, some the far side through the hole.
eye = np.array([0.0, -3.0, 1.0])
targets = np.stack([np.linspace(-1.5, 1.5, 7), np.zeros(7), np.zeros(7)], axis=1)
origins = np.broadcast_to(eye, targets.shape)
directions = targets - eye  # need not be unit length: t is in its units

t = toroid.nearest(major, minor, origins, directions)  # inf where a ray misses
hit = np.isfinite(t)
points = origins[hit] + t[hit, None] * directions[hit]
normals = toroid.normal(major, minor, points)  # unit, outward

print(f"{hit.sum()} of {len(t)} rays hit")
for i, p, n in zip(np.flatnonzero(hit), points, normals):
    print(f"ray {i}: t = {t[i]:.6f}  point = {np.round(p, 6)}  normal = {np.round(n, 6)}")
