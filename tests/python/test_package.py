"""The package: every public function has a docstring and a type stub with the same
parameters, and the package is importable from the build folder alone."""
import ast
import inspect
import os

import zdg

STUB = os.path.join(os.path.dirname(zdg.__file__), "__init__.pyi")


def stub_functions():
    tree = ast.parse(open(STUB).read())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            args = node.args
            out[node.name] = [a.arg for a in args.args + args.kwonlyargs]
    return out


def test_every_public_function_has_a_stub_and_a_docstring():
    stubs = stub_functions()
    assert sorted(stubs) == sorted(zdg.__all__)
    for name in zdg.__all__:
        f = getattr(zdg, name)
        assert f.__doc__ and len(f.__doc__) > 40, name
        if inspect.isfunction(f):  # written in Python (plot, skeleton)
            params = list(inspect.signature(f).parameters)
        else:  # pybind11 functions: "name(arg: type, ...) -> ret" first docstring line
            sig = f.__doc__.splitlines()[0]
            inner = sig[sig.index("(") + 1:sig.rindex(")")]
            params = [p.split(":")[0].strip() for p in inner.split(", ") if p.strip() != "*"]
        assert params == stubs[name], name


def test_the_package_ships_py_typed():
    assert os.path.exists(os.path.join(os.path.dirname(zdg.__file__), "py.typed"))
