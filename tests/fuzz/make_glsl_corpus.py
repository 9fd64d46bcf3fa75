#!/usr/bin/env python3
"""Writes the GLSL fuzzer's seed corpus (tests/fuzz/corpus/glsl/) from piglit's shaders.

Each seed is the input format of tests/fuzz/glsl_fuzzer.cpp: a mode byte (bit 0: desktop GL,
bits 1-2: 1 = vertex shader only, 2 = fragment shader only), then the vertex and the fragment
source separated by a NUL byte. From the GLSL ES 1.00, 1.10 and 1.20 groups: .shader_test files
(both stages) and the compiler tests' .vert/.frag files (one stage), small ones only, a
deterministic sample of each kind.
Usage: make_glsl_corpus.py [PIGLIT_DIR] [OUT_DIR] [PER_KIND]
"""
import hashlib
import pathlib
import re
import sys

piglit = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "/usr/lib/x86_64-linux-gnu/piglit")
out = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else pathlib.Path(__file__).parent / "corpus" / "glsl")
per_kind = int(sys.argv[3]) if len(sys.argv) > 3 else 100
max_bytes = 3000
groups = ["glsl-es-1.00", "glsl-1.10", "glsl-1.20"]
passthrough = "attribute vec4 piglit_vertex;\nvoid main() { gl_Position = piglit_vertex; }\n"


def sample(paths):
    """The per_kind smallest-hash files of those under max_bytes: stable across runs."""
    small = [p for p in paths if p.stat().st_size <= max_bytes]
    return sorted(small, key=lambda p: hashlib.sha1(str(p.relative_to(piglit)).encode()).hexdigest())[:per_kind]


def shader_test_seed(path, es):
    sections, name = {}, None
    for line in path.read_text(errors="replace").splitlines(keepends=True):
        header = re.match(r"^\[([a-z ]+)\]\s*$", line)
        if header:
            name = header.group(1)
            sections[name] = ""
        elif name:
            sections[name] += line
    vertex = sections.get("vertex shader", passthrough if "vertex shader passthrough" in sections else None)
    fragment = sections.get("fragment shader")
    if vertex is None and fragment is None:
        return None
    stages = 0 if vertex is not None and fragment is not None else (1 if vertex is not None else 2)
    return bytes([(0 if es else 1) | stages << 1]) + (vertex or "").encode() + b"\0" + (fragment or "").encode()


def stage_seed(path, es):
    source = path.read_bytes()
    if path.suffix == ".vert":
        return bytes([(0 if es else 1) | 1 << 1]) + source
    return bytes([(0 if es else 1) | 2 << 1]) + b"\0" + source


out.mkdir(parents=True, exist_ok=True)
for old in out.glob("piglit-*"):
    old.unlink()
count = 0
for group in groups:
    es = group.startswith("glsl-es")
    roots = [piglit / "tests" / "spec" / group, piglit / "generated_tests" / "spec" / group]
    kinds = {
        "shader_test": [p for r in roots if r.exists() for p in r.rglob("*.shader_test")],
        "stage": [p for r in roots if r.exists() for p in r.rglob("*") if p.suffix in (".vert", ".frag")],
    }
    for kind, paths in kinds.items():
        for path in sample(paths):
            seed = shader_test_seed(path, es) if kind == "shader_test" else stage_seed(path, es)
            if seed is None:
                continue
            name = "piglit-" + re.sub(r"[^A-Za-z0-9.-]+", "_", str(path.relative_to(piglit / path.parts[len(piglit.parts)] / "spec")))
            (out / name).write_bytes(seed)
            count += 1
print(f"{count} seeds in {out}")
