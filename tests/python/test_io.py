"""Volumes to and from files: round trips through every format keep values and dtype, numpy's
own .npy files are read, and the errors are OSError / ValueError."""
import os

import numpy as np
import pytest

import zdg

hyp = pytest.importorskip("hypothesis")
from hypothesis import given, strategies as st  # noqa: E402
from hypothesis.extra.numpy import arrays  # noqa: E402

# What each format keeps: .vol holds bytes, NIfTI and .npy every numeric type.
FORMATS = {".vol": [np.uint8], ".nii": [np.uint8, np.int16, np.int32, np.float32, np.float64],
           ".nii.gz": [np.uint8, np.uint16, np.int64], ".npy": [np.bool_, np.uint8, np.int8,
                                                              np.uint32, np.int64, np.float64]}


@pytest.mark.parametrize("ext", sorted(FORMATS))
def test_round_trip(tmp_path, ext):
    rng = np.random.default_rng(7)
    for dtype in FORMATS[ext]:
        if dtype == np.bool_:
            a = rng.integers(0, 2, (4, 5, 6)).astype(bool)
        elif np.issubdtype(dtype, np.floating):
            a = rng.normal(size=(4, 5, 6)).astype(dtype)
        else:
            info = np.iinfo(dtype)
            a = rng.integers(max(info.min, -1000), min(info.max, 1000), (4, 5, 6), dtype=dtype,
                             endpoint=True)
        path = str(tmp_path / f"v_{np.dtype(dtype).name}{ext}")
        zdg.write_volume(path, a)
        b = zdg.read_volume(path)
        assert b.dtype == a.dtype and b.shape == a.shape and np.array_equal(a, b)


@given(arrays(st.sampled_from([np.uint8, np.int16, np.float32, np.uint64]),
              st.tuples(st.integers(1, 4), st.integers(1, 4), st.integers(1, 4))))
def test_reads_numpy_npy_files(tmp_path_factory, a):
    path = str(tmp_path_factory.mktemp("npy") / "a.npy")
    np.save(path, a)
    b = zdg.read_volume(path)
    assert b.dtype == a.dtype and np.array_equal(a, b, equal_nan=True)
    # F-ordered arrays are written in C order: the values, not the layout, round trip.
    path2 = path + ".f.npy"
    zdg.write_volume(path2, np.asfortranarray(a))
    assert np.array_equal(np.load(path2), a, equal_nan=True)


def test_metadata_and_existing_outputs(tmp_path):
    a = np.zeros((3, 4, 5), dtype=np.uint8)
    a[1, 2, 3] = 9
    path = str(tmp_path / "a.vol")
    zdg.write_volume(path, a)
    b, meta = zdg.read_volume(path, metadata=True)
    assert np.array_equal(a, b) and meta["format"] == "vol" and len(meta["spacing"]) == 3
    with pytest.raises(OSError, match="exists"):
        zdg.write_volume(path, a)
    zdg.write_volume(path, 2 * a, force=True)
    assert np.array_equal(zdg.read_volume(path), 2 * a)
    with pytest.raises(OSError):
        zdg.read_volume(str(tmp_path / "missing.vol"))
    with pytest.raises(ValueError, match="dtype"):
        zdg.write_volume(str(tmp_path / "c.npy"), np.zeros(3, dtype=np.complex64))
    assert not os.path.exists(tmp_path / "c.npy")


def _nifti2_bytes(dim0, nx=4, ny=3, nz=2, vox_offset=544):
    """A NIfTI-2 single file of uint8 voxels built byte by byte (little-endian)."""
    import struct
    h = bytearray(544)
    struct.pack_into("<i", h, 0, 540)
    h[4:12] = b"n+2\0\r\n\x1a\n"
    struct.pack_into("<hh", h, 12, 2, 8)  # DT_UINT8, 8 bits
    struct.pack_into("<8q", h, 16, dim0, nx, ny, nz, 1, 1, 1, 1)
    struct.pack_into("<8d", h, 104, *([1.0] * 8))
    struct.pack_into("<q", h, 168, vox_offset)
    return bytes(h) + bytes(range(nx * ny * nz))


# Issue #41 item 5: a NIfTI-2 header with dim[0] >= 2^31 crashed the interpreter (SIGSEGV in the
# NIfTI library's header conversion). It is an OSError naming the file, checked first in a
# child interpreter so that a crash fails this test rather than the test runner.
@pytest.mark.parametrize("dim0", [2**31, 2**32 + 3, -1, 0, 8, -2**63])
@pytest.mark.parametrize("ext", [".nii", ".nii.gz"])
def test_nifti2_dim0_out_of_range_is_an_error_not_a_crash(tmp_path, dim0, ext):
    import gzip
    import subprocess
    import sys
    path = str(tmp_path / ("d" + ext))
    data = _nifti2_bytes(dim0)
    with open(path, "wb") as f:
        f.write(gzip.compress(data) if ext == ".nii.gz" else data)
    child = subprocess.run(
        [sys.executable, "-c",
         "import sys, zdg\n"
         "try:\n"
         "    zdg.read_volume(sys.argv[1])\n"
         "except OSError as e:\n"
         "    print(e)\n"
         "    sys.exit(3)\n",
         path], capture_output=True, text=True, timeout=120)
    assert child.returncode == 3, (child.returncode, child.stderr)
    assert child.stdout.startswith(path + ": NIfTI dim[0] = %d (1..7)" % dim0), child.stdout
    with pytest.raises(OSError, match=r"dim\[0\]"):
        zdg.read_volume(path)
    # The same bytes with dim[0] = 3 read as the volume they hold.
    with open(path, "wb") as f:
        data = _nifti2_bytes(3)
        f.write(gzip.compress(data) if ext == ".nii.gz" else data)
    assert np.array_equal(zdg.read_volume(path),
                          np.arange(24, dtype=np.uint8).reshape(2, 3, 4))
