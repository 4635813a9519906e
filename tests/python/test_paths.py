"""Paths: every function of the module that takes a file path refuses a path holding a NUL
byte (the system reads a name up to its first NUL: 'a.npy\\x00b.npy' silently opened a.npy),
whatever the path's type; str, bytes and os.PathLike are accepted."""
import inspect
import os
import pathlib

import numpy as np
import pytest

import zdg

VOLUME = np.arange(8, dtype=np.uint8).reshape(2, 2, 2)

# Every path-taking function, called with the path and whatever else it needs.
CALLS = {
    "read_volume": lambda path: zdg.read_volume(path),
    "write_volume": lambda path: zdg.write_volume(path, VOLUME, force=True),
}

PATH_WORDS = ("path", "file", "dir", "folder", "output")


def parameters(f):
    if inspect.isfunction(f):  # written in Python
        return list(inspect.signature(f).parameters)
    sig = f.__doc__.splitlines()[0]  # pybind11: "name(arg: type, ...) -> ret"
    inner = sig[sig.index("(") + 1:sig.rindex(")")]
    return [p.split(":")[0].strip() for p in inner.split(", ") if p.strip() != "*"]


def test_every_path_taking_function_is_checked():
    taking = {name for name in zdg.__all__
              if any(w in p for p in parameters(getattr(zdg, name)) for w in PATH_WORDS)}
    assert taking == set(CALLS)


@pytest.mark.parametrize("name", sorted(CALLS))
@pytest.mark.parametrize("kind", [str, os.fsencode, pathlib.PurePath])
def test_a_nul_byte_in_a_path_is_refused(tmp_path, monkeypatch, name, kind):
    monkeypatch.chdir(tmp_path)
    np.save("a.npy", VOLUME)
    before = sorted(os.listdir("."))
    with pytest.raises(ValueError, match="NUL byte"):
        CALLS[name](kind("a.npy\x00b.npy"))
    assert sorted(os.listdir(".")) == before
    assert np.array_equal(np.load("a.npy"), VOLUME)


@pytest.mark.parametrize("kind", [str, os.fsencode, pathlib.Path])
def test_paths_of_every_type_are_read_and_written(tmp_path, kind):
    path = kind(str(tmp_path / "v.npy"))
    zdg.write_volume(path, VOLUME)
    assert np.array_equal(zdg.read_volume(path), VOLUME)


def test_a_path_of_another_type_is_a_type_error():
    with pytest.raises(TypeError):
        zdg.read_volume(3)
