"""Prints the folder, relative to the install prefix given as argument, where this Python
interpreter looks for platform-specific packages (python/CMakeLists.txt installs zdg there).

Debian's interpreter: the deb_system scheme for the prefix /usr (lib/python3/dist-packages),
its posix_local scheme for /usr/local (lib/python3.X/dist-packages, computed from the base
/usr); any other prefix, and other interpreters: the standard posix_prefix scheme
(lib/python3.X/site-packages), or the interpreter's default scheme where posix_prefix does
not exist.
"""
import os
import sys
import sysconfig


def install_dir(prefix):
    prefix = os.path.normpath(prefix)
    schemes = sysconfig.get_scheme_names()
    if prefix == "/usr" and "deb_system" in schemes:
        path = sysconfig.get_path("platlib", "deb_system", vars={"base": "/usr", "platbase": "/usr"})
    elif prefix == "/usr/local" and "posix_local" in schemes:
        path = sysconfig.get_path("platlib", "posix_local", vars={"base": "/usr", "platbase": "/usr"})
    else:
        scheme = "posix_prefix" if "posix_prefix" in schemes else sysconfig.get_default_scheme()
        path = sysconfig.get_path("platlib", scheme, vars={"base": prefix, "platbase": prefix})
    rel = os.path.relpath(path, prefix)
    if rel.startswith(".."):
        raise SystemExit("the package folder %s is not under the prefix %s" % (path, prefix))
    return rel


if __name__ == "__main__":
    print(install_dir(sys.argv[1] if len(sys.argv) > 1 else sys.prefix))
