#!/usr/bin/python3
"""The exact distance transform of a scikit-image sample (the horse silhouette, 328 x 400),
compared with scipy.ndimage.distance_transform_edt: the squared, rounded scipy distances
equal zdg's exact integers; times both.

  PYTHONPATH=build/python python3 python/examples/dt_vs_scipy.py
"""
import time

import numpy as np
from scipy import ndimage
from skimage import data

import zdg



def median_ms(f, repeat=7):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(1e3 * (time.perf_counter() - t0))
    return sorted(times)[repeat // 2]


horse = ~data.horse()  # the silhouette is False on a True background
ours = zdg.distance_transform(horse, threads=1)  # bool, C order: read in place
edt = ndimage.distance_transform_edt(horse)
same = np.array_equal(np.rint(edt * edt).astype(np.int64), ours)
t_zdg = median_ms(lambda: zdg.distance_transform(horse, threads=1))
t_scipy = median_ms(lambda: ndimage.distance_transform_edt(horse))
print(f"horse {horse.shape}: zdg {t_zdg:.2f} ms ({ours.dtype}, max d^2 = {ours.max()}), "
      f"scipy {t_scipy:.2f} ms (medians of 7, one thread each); equal after squaring and "
      f"rounding: {same}")
