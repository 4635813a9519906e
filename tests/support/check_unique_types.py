#!/usr/bin/env python3
"""Fails when a class, struct, enum or type alias is defined in two public headers of zdg.

Two headers that both define zdg::Box2 (with different layouts) compile separately but break
the one-definition rule when linked into one program, and clash for a user who includes both.
The headers follow clang-format's LLVM layout (namespace members start at column 0), so a
line scan finds every namespace-level definition. Usage: check_unique_types.py REPO_ROOT
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
definition = re.compile(
    r"^(?:template\s*<.*>\s*)?(?:struct|class|enum class|enum|union)\s+(\w+)\b(?!.*;\s*$)")
alias = re.compile(r"^(?:template\s*<.*>\s*)?using\s+(\w+)\s*=")
open_ns = re.compile(r"^(?:inline\s+)?namespace\s+([\w:]*)\s*\{")
close_ns = re.compile(r"^\}\s*//\s*namespace")

seen = {}
failures = []
for layer in ("arith", "kernel", "estimators", "convergence", "operations"):
    for header in sorted((root / layer).rglob("*.hpp")):
        if "/convergence/check/" in header.as_posix():
            continue
        stack = []
        pending_template = False
        for lineno, line in enumerate(header.read_text().splitlines(), 1):
            if m := open_ns.match(line):
                stack.append(m.group(1) or "<anonymous>")
                continue
            if close_ns.match(line):
                if stack:
                    stack.pop()
                continue
            if not stack or "<anonymous>" in stack:
                continue
            text = line
            if pending_template:
                pending_template = False
            if line.startswith("template <") and line.rstrip().endswith(">"):
                pending_template = True
                continue
            m = definition.match(text) or alias.match(text)
            if not m or text.rstrip().endswith(";") and definition.match(text):
                continue
            key = "::".join(stack) + "::" + m.group(1)
            where = f"{header.relative_to(root)}:{lineno}"
            if key in seen and seen[key].split(":")[0] != where.split(":")[0]:
                failures.append(f"{key} defined in {seen[key]} and in {where}")
            seen.setdefault(key, where)

for f in failures:
    print(f)
print(f"{len(seen)} namespace-level types and aliases, {len(failures)} defined twice")
sys.exit(1 if failures else 0)
