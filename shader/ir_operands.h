// Visiting the registers and constants an instruction reads and the registers it writes
// (a texture lookup's operands live in Code::textures), for the IR passes.
#pragma once
#include "shader/ir.h"

namespace pineda::shader::ir {

// Calls f(Operand&) for every value `in` reads (Gather and Scatter also read and write the
// registers of their dynamic range, which this does not list).
template <class F>
void for_each_use(Code& code, Inst& in, F f) {
  if (in.op == Op::Texture) {
    TextureLookup& t = code.textures[static_cast<size_t>(in.i0)];
    f(t.sampler);
    for (Operand& c : t.coord) f(c);
    if (t.lod != kNone) f(t.lod);
    return;
  }
  if (in.a != kNone) f(in.a);
  if (in.b != kNone) f(in.b);
  if (in.c != kNone) f(in.c);
}

// Calls f(Operand&) for every register `in` writes by name.
template <class F>
void for_each_def(Code& code, Inst& in, F f) {
  if (in.op == Op::Texture) {
    for (Operand& d : code.textures[static_cast<size_t>(in.i0)].dst) f(d);
    return;
  }
  if (in.d != kNone) f(in.d);
}

inline bool is_structure(Op op) { return op <= Op::Discard; }

}  // namespace pineda::shader::ir
