"""The package: every public function and class has a docstring and a type stub with the same
parameters (a class: its public methods and properties), and the package is importable from
the build folder alone."""
import ast
import inspect
import os

import zdg

STUB = os.path.join(os.path.dirname(zdg.__file__), "__init__.pyi")


def parameters(node):
    return [a.arg for a in node.args.args + node.args.kwonlyargs]


def stub_functions():
    """The stub's functions (name: parameters) and classes (name: {method: parameters})."""
    tree = ast.parse(open(STUB).read())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            out[node.name] = parameters(node)
        elif isinstance(node, ast.ClassDef) and any(isinstance(n, ast.FunctionDef)
                                                    for n in node.body):
            out[node.name] = {n.name: parameters(n) for n in node.body
                              if isinstance(n, ast.FunctionDef)}
    return out


def test_every_public_function_has_a_stub_and_a_docstring():
    stubs = stub_functions()
    assert sorted(stubs) == sorted(zdg.__all__)
    for name in zdg.__all__:
        f = getattr(zdg, name)
        if inspect.isclass(f):  # written in Python (Viewer)
            assert f.__doc__ and len(f.__doc__) > 40, name
            methods = {m: list(inspect.signature(v.fget if isinstance(v, property) else v)
                               .parameters)
                       for m, v in vars(f).items()
                       if (not m.startswith("_") or m in ("__init__", "_repr_html_"))
                       and (inspect.isfunction(v) or isinstance(v, property))}
            assert methods == stubs[name], name
            continue
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
