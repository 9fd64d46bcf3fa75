#include "shader/unroll_loops.h"

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <vector>

#include "shader/ir_operands.h"

namespace pineda::shader {

using ir::Inst;
using ir::kNone;
using ir::Op;
using ir::Operand;

namespace {

constexpr int kMaxTripCount = 256;
constexpr size_t kMaxInstructions = 4096;  // the whole stage after unrolling

struct Loop {
  int begin = -1;  // LoopBegin
  int test = -1;   // its BreakIfNot, after the header computing the test
  int cont = -1;   // ContinuePoint
  int end = -1;    // LoopEnd
};

// Loops innermost first (in the order their LoopEnd closes them).
std::vector<Loop> find_loops(const ir::Code& code) {
  std::vector<Loop> loops, open;
  for (int pc = 0; pc < static_cast<int>(code.insts.size()); ++pc) {
    const Op op = code.insts[static_cast<size_t>(pc)].op;
    if (op == Op::LoopBegin) open.push_back(Loop{pc});
    if (open.empty()) continue;
    if (op == Op::ContinuePoint) open.back().cont = pc;
    if (op == Op::LoopEnd) {
      open.back().end = pc;
      loops.push_back(open.back());
      open.pop_back();
    }
  }
  return loops;
}

bool opens(Op op) { return op == Op::IfBegin || op == Op::LoopBegin || op == Op::FuncBegin; }
bool closes(Op op) { return op == Op::EndIf || op == Op::LoopEnd || op == Op::FuncEnd; }

// The constant that the last write of `reg` before `pc` stores, when that write is a move of
// a constant in the same region as pc (no structure between them opens around pc).
std::optional<float> constant_before(const ir::Code& code, int pc, Operand reg) {
  int depth = 0;  // constructs entered while walking back
  for (int q = pc - 1; q >= 0; --q) {
    const Inst& in = code.insts[static_cast<size_t>(q)];
    if (closes(in.op)) ++depth;
    else if (opens(in.op) && depth-- == 0) return std::nullopt;  // pc's region starts here
    else if ((in.op == Op::Else || in.op == Op::ContinuePoint) && depth == 0) return std::nullopt;
    bool writes = false;
    ir::for_each_def(const_cast<ir::Code&>(code), const_cast<Inst&>(in), [&](Operand& d) { writes = writes || d == reg; });
    if (!writes) continue;
    if (depth != 0 || in.op != Op::Mov || !ir::is_const(in.a)) return std::nullopt;
    return code.const_value(in.a);
  }
  return std::nullopt;
}

// Runs the pure arithmetic instructions [from, to) on scalar values; false when one reads a
// register with no value.
bool simulate(const ir::Code& code, int from, int to, std::unordered_map<Operand, float>& values) {
  auto read = [&](Operand o, float& v) {
    if (ir::is_const(o)) {
      v = code.const_value(o);
      return true;
    }
    auto it = values.find(o);
    if (it == values.end()) return false;
    v = it->second;
    return true;
  };
  for (int pc = from; pc < to; ++pc) {
    const Inst& in = code.insts[static_cast<size_t>(pc)];
    float a = 0, b = 0, c = 0;
    const int n = ir::op_arity(in.op);
    if (!read(in.a, a) || (n >= 2 && !read(in.b, b)) || (n >= 3 && !read(in.c, c))) return false;
    values[in.d] = n == 1 ? ir::eval_unary(in.op, a) : n == 2 ? ir::eval_binary(in.op, a, b) : ir::eval_ternary(in.op, a, b, c);
  }
  return true;
}

bool pure_arith_range(const ir::Code& code, int from, int to) {
  for (int pc = from; pc < to; ++pc) {
    const Inst& in = code.insts[static_cast<size_t>(pc)];
    if (!ir::op_is_pure_arith(in.op) || in.d < 0) return false;
  }
  return true;
}

// The number of iterations `loop` runs, when it can be unrolled.
std::optional<int> trip_count(ir::Code& code, Loop& loop) {
  if (loop.cont < 0) return std::nullopt;
  loop.test = loop.begin + 1;
  while (loop.test < loop.cont && ir::op_is_pure_arith(code.insts[static_cast<size_t>(loop.test)].op)) ++loop.test;
  const Inst& test = code.insts[static_cast<size_t>(loop.test)];
  if (test.op != Op::BreakIfNot || test.a < 0) return std::nullopt;
  if (!pure_arith_range(code, loop.begin + 1, loop.test) || !pure_arith_range(code, loop.cont + 1, loop.end))
    return std::nullopt;

  // The registers the header and the increment read and write.
  std::vector<Operand> touched;
  auto note = [&](Operand o) {
    if (o >= 0 && std::find(touched.begin(), touched.end(), o) == touched.end()) touched.push_back(o);
  };
  std::unordered_map<Operand, float> values;
  std::vector<Operand> written;
  auto scan = [&](int from, int to) -> bool {
    for (int pc = from; pc < to; ++pc) {
      Inst& in = code.insts[static_cast<size_t>(pc)];
      bool ok = true;
      ir::for_each_use(code, in, [&](Operand& o) {
        note(o);
        if (o < 0 || values.count(o) || std::find(written.begin(), written.end(), o) != written.end()) return;
        const std::optional<float> v = constant_before(code, loop.begin, o);
        if (v) values[o] = *v;
        else ok = false;
      });
      if (!ok) return false;
      note(in.d);
      written.push_back(in.d);
    }
    return true;
  };
  if (!scan(loop.begin + 1, loop.test) || !scan(loop.cont + 1, loop.end)) return std::nullopt;

  // The body changes none of them, reaches none through an index, and leaves only the loops
  // it holds.
  int nested = 0;
  for (int pc = loop.test + 1; pc < loop.cont; ++pc) {
    Inst& in = code.insts[static_cast<size_t>(pc)];
    if (in.op == Op::LoopBegin) ++nested;
    if (in.op == Op::LoopEnd) --nested;
    if (nested == 0 && (in.op == Op::Break || in.op == Op::Continue || in.op == Op::BreakIfNot)) return std::nullopt;
    bool clash = false;
    ir::for_each_def(code, in, [&](Operand& d) { clash = clash || std::find(touched.begin(), touched.end(), d) != touched.end(); });
    if (clash) return std::nullopt;
  }
  for (const Inst& in : code.insts)
    if (in.op == Op::Gather || in.op == Op::Scatter)
      for (Operand r : touched)
        if (r >= in.i0 && r <= in.i0 + in.i1) return std::nullopt;

  for (int trips = 0; trips <= kMaxTripCount; ++trips) {
    if (!simulate(code, loop.begin + 1, loop.test, values)) return std::nullopt;
    if (values[test.a] == 0.0f) return trips;
    if (!simulate(code, loop.cont + 1, loop.end, values)) return std::nullopt;
  }
  return std::nullopt;
}

// Appends code.insts[from, to) to `out`, each texture lookup with a lookup of its own.
void copy_range(ir::Code& code, int from, int to, std::vector<Inst>& out) {
  for (int pc = from; pc < to; ++pc) {
    Inst in = code.insts[static_cast<size_t>(pc)];
    if (in.op == Op::Texture) {
      const ir::TextureLookup lookup = code.textures[static_cast<size_t>(in.i0)];
      code.textures.push_back(lookup);
      in.i0 = static_cast<int32_t>(code.textures.size() - 1);
    }
    out.push_back(in);
  }
}

bool unroll_one(ir::Code& code) {
  for (Loop loop : find_loops(code)) {
    const std::optional<int> trips = trip_count(code, loop);
    if (!trips) continue;
    const size_t header = static_cast<size_t>(loop.test - loop.begin - 1);
    const size_t iteration = static_cast<size_t>(loop.end - loop.begin - 3);  // without begin, test, cont, end
    const size_t size = code.insts.size() - static_cast<size_t>(loop.end - loop.begin + 1) +
                        static_cast<size_t>(*trips) * iteration + header;
    if (size > kMaxInstructions) continue;
    std::vector<Inst> out(code.insts.begin(), code.insts.begin() + loop.begin);
    out.reserve(size);
    for (int t = 0; t < *trips; ++t) {
      copy_range(code, loop.begin + 1, loop.test, out);
      copy_range(code, loop.test + 1, loop.cont, out);
      copy_range(code, loop.cont + 1, loop.end, out);
    }
    copy_range(code, loop.begin + 1, loop.test, out);
    out.insert(out.end(), code.insts.begin() + loop.end + 1, code.insts.end());
    code.insts = std::move(out);
    return true;
  }
  return false;
}

}  // namespace

bool unroll_constant_loops(ir::Code& code) {
  bool any = false;
  while (unroll_one(code)) any = true;
  return any;
}

}  // namespace pineda::shader
