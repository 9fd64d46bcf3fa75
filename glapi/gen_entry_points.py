#!/usr/bin/env python3
"""Generates Pineda's exported GL and EGL entry points from the Khronos XML registry.

Only the functions listed in gl_functions.txt / egl_functions.txt are generated: those are
the ones Pineda implements, so they are the only ones exported or returned by
GetProcAddress. Every prototype comes from gl.xml / egl.xml.

An OpenGL ES 1.1 context reaches only the functions of gl.xml's GL_VERSION_ES_CM_1_0 feature
and of the extensions in es1_extensions.txt, and only with the enums they define; an OpenGL ES
2.0 context likewise GL_ES_VERSION_2_0 and es2_extensions.txt; any other
call records GL_INVALID_OPERATION (what Mesa does for a function outside the context's API),
any other enum value GL_INVALID_ENUM. Functions flagged es_only are refused the same way by
desktop GL contexts.

Outputs (in --out): gl_entry_points.h/.cpp, egl_entry_points.h/.cpp. A file is rewritten only
when its contents change, so that an unchanged list does not trigger a rebuild.
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

# After these GL calls the rendering is complete: a window-system binding that keeps a
# converted copy of the framebuffer (OSMesa's 3-byte formats) is told to update it.
FLUSH_FUNCTIONS = {"glFinish", "glFlush"}

# The calls that change no state a draw works out from it (state/state_key.h): the array draws
# and glGetError. Every other call counts itself as one that may.
STATE_KEEPING_FUNCTIONS = {"glDrawArrays", "glDrawArraysEXT", "glDrawElements", "glDrawRangeElements",
                           "glDrawRangeElementsEXT", "glMultiDrawArrays", "glMultiDrawArraysEXT",
                           "glMultiDrawElements", "glMultiDrawElementsEXT", "glGetError"}


class Command:
    def __init__(self, name, ret, params, lens=None, elements=None):
        self.name = name
        self.ret = ret          # C return type, e.g. "const GLubyte *"
        self.params = params    # list of (declaration, name)
        self.lens = lens or {}          # pointer parameter name -> registry "len" attribute
        self.elements = elements or {}  # pointer parameter name -> element type

    def param_decls(self):
        return ", ".join(decl for decl, _ in self.params) if self.params else "void"

    def param_names(self):
        return ", ".join(name for _, name in self.params)


def split_named(elem):
    """Returns (text before <name>, name, text after <name>) of a <proto> or <param>."""
    before, after, name, seen = [], [], None, False
    if elem.text:
        before.append(elem.text)
    for child in elem:
        if child.tag == "name":
            name, seen = child.text, True
        else:
            (after if seen else before).append("".join(child.itertext()))
        if child.tail:
            (after if seen else before).append(child.tail)
    return " ".join("".join(before).split()), name, "".join(after).strip()


def read_commands(xml_path):
    root = ET.parse(xml_path).getroot()
    commands = {}
    for cmd in root.find("commands").findall("command"):
        ret, name, _ = split_named(cmd.find("proto"))
        params, lens, elements = [], {}, {}
        for p in cmd.findall("param"):
            ptype, pname, suffix = split_named(p)
            params.append((f"{ptype} {pname}{suffix}", pname))
            if "*" in ptype:
                lens[pname] = p.get("len")
                elements[pname] = ptype.replace("const", "").replace("*", "").strip()
        commands[name] = Command(name, ret, params, lens, elements)
    return commands


# Enum values an ES context takes beyond its feature and extensions. GL_MAX_CLIP_PLANES:
# piglit's shader_runner_gles2 asks every ES 2.0 context for it (state/es2/es2_get.cpp).
EXTRA_ENUMS = {"gles1": [], "gles2": ["GL_MAX_CLIP_PLANES"]}


def read_es_api(xml_path, api, feature, extensions):
    """The commands and enum values an OpenGL ES context offers: gl.xml's `feature` of `api`
    ("gles1": GL_VERSION_ES_CM_1_0, "gles2": GL_ES_VERSION_2_0 only, not the later versions)
    and the listed extensions' requirements for that api."""
    root = ET.parse(xml_path).getroot()
    values = {}
    for group in root.findall("enums"):
        for e in group.findall("enum"):
            if e.get("api") in (None, api) and e.get("name") not in values:
                values[e.get("name")] = int(e.get("value"), 0)
    requires = []
    for f in root.findall("feature"):
        if f.get("api") == api and f.get("name") == feature:
            requires += [r for r in f.findall("require") if r.get("api") in (None, api)]
    if not requires:
        sys.exit(f"{feature}: not a feature of {api} in the registry")
    known = {e.get("name"): e for e in root.find("extensions")}
    for name in extensions:
        ext = known.get(name)
        if ext is None or api not in ext.get("supported").split("|"):
            sys.exit(f"{name}: not a {api} extension of the registry")
        requires += [r for r in ext.findall("require") if r.get("api") in (None, api)]
    commands, enums = set(), {values[name] for name in EXTRA_ENUMS[api]}
    for r in requires:
        commands |= {c.get("name") for c in r.findall("command")}
        enums |= {values[e.get("name")] for e in r.findall("enum")}
    return commands, enums


def read_list(path):
    """One function per line, optional flags after it; '#' starts a comment."""
    entries = []
    with open(path) as f:
        for lineno, line in enumerate(f, 1):
            words = line.split("#", 1)[0].split()
            if words:
                entries.append((words[0], set(words[1:]), lineno))
    return entries


def select(commands, entries, list_path, prefix, known_flags):
    selected, seen = [], set()
    for name, flags, lineno in entries:
        where = f"{list_path}:{lineno}"
        if name in seen:
            sys.exit(f"{where}: {name} is listed twice")
        if name not in commands:
            sys.exit(f"{where}: {name} is not in the registry")
        if not name.startswith(prefix):
            sys.exit(f"{where}: {name} does not start with {prefix}")
        unknown = {f for f in flags if not f.startswith("=")} - known_flags
        if unknown:
            sys.exit(f"{where}: unknown flag(s) {' '.join(sorted(unknown))}")
        seen.add(name)
        selected.append((commands[name], flags))
    return selected


def list_recording(cmd, flags):
    """The lines that record a call into the display list being compiled (GL 1.1 spec 5.4).

    Pointer arguments are copied now, as GL requires: `len` of the registry gives their size
    (a number, another parameter, or COMPSIZE(pname) for the parameter-vector calls)."""
    if cmd.ret != "void" or "not_compiled" in flags:
        return []
    args = [n for _, n in cmd.params]
    if "compile_custom" in flags:
        return ["  if (ctx->compiling_list()) {",
                f"    pineda::gl::compile_{cmd.name[2:]}({', '.join(['*ctx'] + args)});",
                "    if (!ctx->executing_while_compiling()) return;",
                "  }"]
    lines, call_args = ["  if (ctx->compiling_list()) {"], []
    names = {n for _, n in cmd.params}
    for _, n in cmd.params:
        if n not in cmd.lens:
            call_args.append(n)
            continue
        length, element = cmd.lens[n], cmd.elements[n]
        if length is None or element == "void":
            sys.exit(f"{cmd.name}: parameter {n} has no usable length: flag it compile_custom or not_compiled")
        if length.isdigit():
            count = length
        elif length in names:
            count = f"static_cast<size_t>({length} > 0 ? {length} : 0)"
        elif length == "COMPSIZE(pname)":
            count = "pineda::gl::list_param_count(pname)"
        else:
            sys.exit(f"{cmd.name}: parameter {n} has length {length}: flag it compile_custom or not_compiled")
        lines.append(f"    pineda::glapi::ListCopy<{element}> {n}_copy({n}, {count});")
        call_args.append(f"{n}_copy.get()")
    captures = ", ".join(n if n not in cmd.lens else f"{n}_copy" for _, n in cmd.params)
    # The replayed context's name must not be a GL parameter's (glIndexd has one called `c`).
    body = f"pineda::gl::{cmd.name[2:]}({', '.join(['list_ctx'] + call_args)});"
    if "inside_begin_end" not in flags:
        body = ("if (list_ctx.inside_begin_end()) { "
                "list_ctx.record_error(GL_INVALID_OPERATION, \"called between glBegin and glEnd\"); return; } " + body)
    lines.append(f"    ctx->record_list_command([{captures}](pineda::Context& list_ctx) {{ {body} }});")
    lines.append("    if (!ctx->executing_while_compiling()) return;")
    lines.append("  }")
    return lines


def impl_name(cmd, flags):
    """`=glOther` makes a function another name of glOther (the OES suffixes of ES 1.1)."""
    for f in flags:
        if f.startswith("="):
            return f[3:]
    return cmd.name[2:]


ES_APIS = (("es1", "OpenGL ES 1.1"), ("es2", "OpenGL ES 2.0"))


def api_gate(cmd, flags, es_commands):
    """The lines that refuse a call the context's API does not have. `es_commands` maps
    "es1"/"es2" to the commands of that API."""
    lines = []
    enum_params = [n for d, n in cmd.params if d.split()[0] == "GLenum" and "*" not in d]
    for kind, title in ES_APIS:
        if cmd.name not in es_commands[kind]:
            lines += [f"  if (ctx->{kind}()) {{", f'    ctx->record_error(GL_INVALID_OPERATION, "not a command of {title}");',
                      f"    {zero_return(cmd)}", "  }"]
        elif enum_params:
            test = " || ".join(f"!pineda::glapi::{kind}_enum({n})" for n in enum_params)
            lines += [f"  if (ctx->{kind}() && ({test})) {{", f'    ctx->record_error(GL_INVALID_ENUM, "an enum {title} does not have");',
                      f"    {zero_return(cmd)}", "  }"]
    if "es_only" in flags:
        lines += ["  if (!ctx->attribs().gles) {", '    ctx->record_error(GL_INVALID_OPERATION, "an OpenGL ES command");',
                  f"    {zero_return(cmd)}", "  }"]
    return lines


def out_of_memory_guard(cmd, body):
    """The body in the one place where an allocation the machine cannot hold is caught: it
    records GL_OUT_OF_MEMORY (GL 1.5 2.5). The implementation allocates before it changes
    state, so the state stays as it was before the failing allocation."""
    lines = ["  try {"] + ["  " + line for line in body]
    lines += ["  } catch (const std::bad_alloc&) {",
              "    ctx->record_error(GL_OUT_OF_MEMORY, \"the memory this call needs could not be allocated\");",
              "  } catch (const std::length_error&) {  // a size beyond what a std::vector can hold",
              "    ctx->record_error(GL_OUT_OF_MEMORY, \"the memory this call needs could not be allocated\");",
              "  }"]
    if cmd.ret != "void":
        lines.append("  return {};")
    return lines


def zero_return(cmd):
    return "return;" if cmd.ret == "void" else "return {};"


def proc_table(function_name, commands):
    lines = [f"void* {function_name}(const char* name) {{",
             "  struct Entry { const char* name; void* proc; };",
             "  static const Entry kTable[] = {"]
    for cmd in sorted(commands, key=lambda c: c.name.encode()):
        lines.append(f'      {{"{cmd.name}", reinterpret_cast<void*>(&::{cmd.name})}},')
    if not commands:
        lines.append('      {"", nullptr},')
    lines += ["  };",
              "  if (!name) return nullptr;",
              "  const Entry* end = kTable + sizeof(kTable) / sizeof(kTable[0]);",
              "  const Entry* it = std::lower_bound(kTable, end, name,",
              "      [](const Entry& e, const char* n) { return std::strcmp(e.name, n) < 0; });",
              "  return (it != end && std::strcmp(it->name, name) == 0) ? it->proc : nullptr;",
              "}"]
    return "\n".join(lines)


HEADER_NOTE = "// Generated by glapi/gen_entry_points.py from the Khronos registry. Do not edit.\n"


def es_enum_table(kind, enums):
    lines = [f"bool {kind}_enum(GLenum value) {{", "  static const GLenum kValues[] = {"]
    row = []
    for v in sorted(enums):
        row.append(f"0x{v:04X}")
        if len(row) == 8:
            lines.append("      " + ", ".join(row) + ",")
            row = []
    if row:
        lines.append("      " + ", ".join(row) + ",")
    lines += ["  };",
              "  return std::binary_search(std::begin(kValues), std::end(kValues), value);",
              "}"]
    return "\n".join(lines)


def gl_outputs(selected, es_commands, es_enums, es_extensions):
    h = [HEADER_NOTE, "#pragma once", "#include <GL/gl.h>", "#include <GL/glext.h>", "#include <cstddef>", "",
         "// OpenGL ES 1.1's type (GLES/gl.h), which GL/glext.h does not define.",
         "typedef khronos_int32_t GLclampx;",
         "// GL_KHR_debug's callback type in OpenGL ES (GLES2/gl2ext.h): the same as GLDEBUGPROC.",
         "typedef GLDEBUGPROC GLDEBUGPROCKHR;", "",
         "namespace pineda { class Context; }", "", "namespace pineda::gl {", ""]
    for cmd, flags in selected:
        params = ", ".join(["Context& ctx"] + [d for d, _ in cmd.params])
        if impl_name(cmd, flags) != cmd.name[2:]:
            continue
        h.append(f"{cmd.ret} {cmd.name[2:]}({params});")
        if "compile_custom" in flags:
            h.append(f"void compile_{cmd.name[2:]}({params});")
    h += ["", "// Values a parameter-vector call (glLightfv, glTexParameterfv...) reads for `pname`.",
          "size_t list_param_count(GLenum pname);", "", "}  // namespace pineda::gl", "",
          "namespace pineda::glapi {", "",
          "// Whether an OpenGL ES 1.1 / 2.0 context knows the enum value (gl.xml, es1/es2_extensions.txt).",
          "bool es1_enum(GLenum value);",
          "bool es2_enum(GLenum value);",
          "// GL_EXTENSIONS of an OpenGL ES 1.1 / 2.0 context (es1/es2_extensions.txt), with a trailing space.",
          f'inline constexpr const char* kES1Extensions = "{" ".join(es_extensions["es1"])} ";',
          f'inline constexpr const char* kES2Extensions = "{" ".join(es_extensions["es2"])} ";',
          "", "}  // namespace pineda::glapi", ""]

    c = [HEADER_NOTE, "#include <algorithm>", "#include <cstring>", "#include <iterator>", "#include <new>", "#include <stdexcept>", "",
         '#include "glapi/gl_entry_points.h"', '#include "glapi/current.h"',
         '#include "glapi/flush_listener.h"', '#include "glapi/list_copy.h"', '#include "glapi/proc_table.h"',
         '#include "state/context.h"', "",
         "#define PINEDA_EXPORT extern \"C\" __attribute__((visibility(\"default\")))", ""]
    for cmd, flags in selected:
        args = ", ".join(["*ctx"] + [n for _, n in cmd.params])
        c.append(f"PINEDA_EXPORT {cmd.ret} GLAPIENTRY {cmd.name}({cmd.param_decls()}) {{")
        c.append("  pineda::Context* ctx = pineda::current_context();")
        c.append(f"  if (!ctx) {zero_return(cmd)}")
        c.append("  const auto shared_lock = pineda::lock_if_shared(*ctx->share_group());")
        c.append(f'  ctx->current_call = "{cmd.name}";')
        if cmd.name not in STATE_KEEPING_FUNCTIONS:
            c.append("  ctx->count_state_call(shared_lock.locked());")
        body = api_gate(cmd, flags, es_commands)
        body += list_recording(cmd, flags)
        if "inside_begin_end" not in flags:
            body.append("  if (ctx->inside_begin_end()) {")
            body.append('    ctx->record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");')
            body.append(f"    {zero_return(cmd)}")
            body.append("  }")
        call = f"pineda::gl::{impl_name(cmd, flags)}({args})"
        if cmd.name in FLUSH_FUNCTIONS:
            body.append(f"  {call};")
            body.append("  pineda::glapi::notify_flushed(*ctx);")
        elif cmd.ret == "void":
            body.append(f"  {call};")
        else:
            body.append(f"  return {call};")
        c += out_of_memory_guard(cmd, body)
        c.append("}")
        c.append("")
    c += ["namespace pineda::glapi {", "", proc_table("lookup_gl_proc", [cmd for cmd, _ in selected]),
          "", es_enum_table("es1", es_enums["es1"]), "", es_enum_table("es2", es_enums["es2"]), "",
          "}  // namespace pineda::glapi", ""]
    return "\n".join(h), "\n".join(c)


def egl_outputs(selected):
    h = [HEADER_NOTE, "#pragma once", "#include <EGL/egl.h>", "#include <EGL/eglext.h>", "",
         "namespace pineda::egl {", ""]
    for cmd, _ in selected:
        h.append(f"{cmd.ret} {cmd.name[3:]}({cmd.param_decls()});")
    h += ["", "}  // namespace pineda::egl", ""]

    c = [HEADER_NOTE, "#include <algorithm>", "#include <cstring>", "#include <iterator>", "",
         '#include "glapi/egl_entry_points.h"', '#include "glapi/proc_table.h"', "",
         "#define PINEDA_EXPORT extern \"C\" __attribute__((visibility(\"default\")))", ""]
    for cmd, _ in selected:
        call = f"pineda::egl::{cmd.name[3:]}({cmd.param_names()})"
        c.append(f"PINEDA_EXPORT {cmd.ret} EGLAPIENTRY {cmd.name}({cmd.param_decls()}) {{")
        c.append(f"  {call};" if cmd.ret == "void" else f"  return {call};")
        c.append("}")
        c.append("")
    c += ["namespace pineda::glapi {", "", proc_table("lookup_egl_proc", [cmd for cmd, _ in selected]),
          "", "}  // namespace pineda::glapi", ""]
    return "\n".join(h), "\n".join(c)


def write_if_changed(path, text):
    try:
        with open(path) as f:
            if f.read() == text:
                return
    except FileNotFoundError:
        pass
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--gl-xml", required=True)
    ap.add_argument("--egl-xml", required=True)
    ap.add_argument("--gl-list", required=True)
    ap.add_argument("--egl-list", required=True)
    ap.add_argument("--es1-extensions", required=True, help="the extensions of OpenGL ES 1.1 contexts")
    ap.add_argument("--es2-extensions", required=True, help="the extensions of OpenGL ES 2.0 contexts")
    ap.add_argument("--out", required=True, help="directory for the generated files")
    args = ap.parse_args()

    gl = select(read_commands(args.gl_xml), read_list(args.gl_list), args.gl_list, "gl",
                {"inside_begin_end", "not_compiled", "compile_custom", "es_only"})
    es_extensions, es_commands, es_enums = {}, {}, {}
    for kind, api, feature, path in (("es1", "gles1", "GL_VERSION_ES_CM_1_0", args.es1_extensions),
                                     ("es2", "gles2", "GL_ES_VERSION_2_0", args.es2_extensions)):
        es_extensions[kind] = [name for name, _, _ in read_list(path)]
        es_commands[kind], es_enums[kind] = read_es_api(args.gl_xml, api, feature, es_extensions[kind])
        missing = sorted(es_commands[kind] - {cmd.name for cmd, _ in gl})
        if missing:
            sys.exit(f"{feature} functions not in {args.gl_list}: {' '.join(missing)}")
    egl = select(read_commands(args.egl_xml), read_list(args.egl_list), args.egl_list, "egl",
                 set())
    os.makedirs(args.out, exist_ok=True)
    gl_h, gl_c = gl_outputs(gl, es_commands, es_enums, es_extensions)
    egl_h, egl_c = egl_outputs(egl)
    write_if_changed(os.path.join(args.out, "gl_entry_points.h"), gl_h)
    write_if_changed(os.path.join(args.out, "gl_entry_points.cpp"), gl_c)
    write_if_changed(os.path.join(args.out, "egl_entry_points.h"), egl_h)
    write_if_changed(os.path.join(args.out, "egl_entry_points.cpp"), egl_c)


if __name__ == "__main__":
    main()
