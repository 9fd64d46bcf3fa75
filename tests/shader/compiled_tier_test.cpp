// The compiled tier (shader/jit/) gives exactly the interpreter's bits (NaNs: any NaN): every operation over
// special values (signed zeros, denormals, NaNs, infinities, the 2^23 rounding edge), with
// operands from registers, constants and uniform slots, under register pressure that spills,
// through call-outs (texture-free ones here; images cover texture lookups), and with
// `if (c) discard;` (the discarded lanes too).
#include <gtest/gtest.h>
#include <xmmintrin.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "shader/execute.h"
#include "tests/shader/shader_test_util.h"
#include "shader/jit/compiled_stage.h"

namespace pineda::shader::test {
namespace {

using ir::Op;
using ir::Operand;

constexpr uint32_t kSpecialBits[] = {
    0x00000000, 0x80000000, 0x3F800000, 0xBF800000, 0x3F000000, 0xBF000000, 0x3FC00000, 0xBFC00000,
    0x4B000000, 0xCB000000, 0x4AFFFFFF, 0xCAFFFFFF, 0x4B000001, 0x7149F2CA, 0xF149F2CA, 0x7F800000,
    0xFF800000, 0x7FC00000, 0xFFC00000, 0x7FA00000, 0x00000001, 0x80000001, 0x00800000, 0x80800000,
    0x40400000, 0x3DCCCCCD, 0x42C88000, 0xC0F80000, 0x3F7FFFFF, 0xBF7FFFFF, 0x40490FDB, 0xC2C80000};

float special(std::mt19937& random) {
  std::uniform_int_distribution<int> pick(0, static_cast<int>(std::size(kSpecialBits)) * 2 - 1);
  const int i = pick(random);
  if (i < static_cast<int>(std::size(kSpecialBits))) return std::bit_cast<float>(kSpecialBits[i]);
  return std::uniform_real_distribution<float>(-300.0f, 300.0f)(random);
}

struct Block {
  std::vector<float> varyings = std::vector<float>(8 * kLanes);
  FragmentBlock fragment{};
};

// Runs `stage` over `block` with the compiled code or the interpreter; returns colour 0's lanes
// and the vertex outputs.
std::vector<uint32_t> run(const StageCode& stage, Stage kind, Block block, const std::vector<float>& uniforms,
                          bool compiled, const TextureAccess* textures) {
  StageCode copy = stage;
  if (!compiled) copy.compiled = nullptr;
  LaneIo io;
  io.uniforms = uniforms.data();
  io.textures = textures;
  std::vector<float> outputs(8 * kLanes, 0.0f);
  block.fragment.varyings = block.varyings.data();
  io.blocks[0] = &block.fragment;
  io.inputs[0] = block.varyings.data();
  io.outputs[0] = outputs.data();
  std::vector<float> slots(static_cast<size_t>(stage.slots + 1) * kLanes);
  stage.compute_uniform_ops(uniforms.data(), slots.data());
  io.slot_lanes = slots.data();
  const RunMask discarded = execute(copy, kind, 1, 0xFFFF, io);
  std::vector<uint32_t> bits = {static_cast<uint32_t>(discarded)};
  // A discarded lane's colour is never used: the interpreter stops computing it.
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < kLanes; ++l)
      bits.push_back((discarded >> l & 1) ? 0u : std::bit_cast<uint32_t>(block.fragment.color[0][c][l]));
  for (float v : outputs) bits.push_back(std::bit_cast<uint32_t>(v));
  return bits;
}

Block random_block(std::mt19937& random) {
  Block b;
  for (float& v : b.varyings) v = special(random);
  b.fragment.live = 0xFFFF;
  b.fragment.front_facing = static_cast<LaneMask>(random());
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < kLanes; ++l) b.fragment.frag_coord[c][l] = special(random);
  for (int c = 0; c < 2; ++c)
    for (int l = 0; l < kLanes; ++l) b.fragment.point_coord[c][l] = special(random);
  return b;
}

// A NaN's sign and payload depend on which operand x86 propagates, that is on the operand
// order the compiler picked for a commutative operation; GLSL cannot observe them (every
// comparison, conversion and write treats all NaNs alike), so any NaN matches any NaN.
bool is_nan(uint32_t bits) { return (bits & 0x7F800000u) == 0x7F800000u && (bits & 0x007FFFFFu) != 0; }

// Both tiers over many random blocks (of special values by default); the stage must have compiled.
void expect_same_bits(ir::Code code, Stage kind, const std::vector<float>& uniforms, const char* what,
                      Block (*make_block)(std::mt19937&) = random_block, const TextureAccess* textures = nullptr) {
  StageCode stage;
  stage.code = std::move(code);
  stage.prepare();
  ASSERT_NE(stage.compiled, nullptr) << what;
  std::mt19937 random(7);
  for (int trial = 0; trial < 200; ++trial) {
    const Block block = make_block(random);
    const std::vector<uint32_t> interpreted = run(stage, kind, block, uniforms, false, textures);
    const std::vector<uint32_t> compiled = run(stage, kind, block, uniforms, true, textures);
    for (size_t i = 0; i < interpreted.size(); ++i) {
      if (is_nan(compiled[i]) && is_nan(interpreted[i])) continue;
      ASSERT_EQ(compiled[i], interpreted[i]) << what << " trial " << trial << " value " << i;
    }
  }
}

class CompiledTier : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!jit::compiled_tier_enabled()) GTEST_SKIP() << "no AVX-512 or PINEDA_SHADER_JIT=0";
  }
};

Operand load(ir::Code& code, Stage kind, int index) {
  const Operand r = code.new_register();
  code.insts.push_back(ir::Inst{kind == Stage::Fragment ? Op::LoadVarying : Op::LoadInput, r, ir::kNone, ir::kNone,
                                ir::kNone, index, 0});
  return r;
}
void store(ir::Code& code, Stage kind, Operand value, int index) {
  code.insts.push_back(ir::Inst{kind == Stage::Fragment ? Op::StoreColor : Op::StoreOutput, ir::kNone, value,
                                ir::kNone, ir::kNone, index, 0});
}

// n values x * c + step * i, for more values live at once than registers.
std::vector<Operand> many_values(ir::Code& code, Operand x, Operand c, int n, float step) {
  std::vector<Operand> values;
  for (int i = 0; i < n; ++i) {
    values.push_back(code.new_register());
    code.insts.push_back(ir::Inst{Op::Mad, values.back(), x, c, code.constant(step * static_cast<float>(i)), 0, 0});
  }
  return values;
}
// first + the sum of `values`, in order.
Operand sum_of(ir::Code& code, Operand first, const std::vector<Operand>& values) {
  Operand sum = first;
  for (Operand v : values) {
    const Operand next = code.new_register();
    code.insts.push_back(ir::Inst{Op::Add, next, sum, v, ir::kNone, 0, 0});
    sum = next;
  }
  return sum;
}

TEST_F(CompiledTier, EveryOperationGivesTheInterpretersBits) {
  for (Stage kind : {Stage::Fragment, Stage::Vertex}) {
    for (int o = static_cast<int>(Op::Mov); o < static_cast<int>(Op::Count); ++o) {
      const Op op = static_cast<Op>(o);
      if (op != Op::Mov && op < Op::Neg) continue;
      const int arity = op == Op::Mov ? 1 : ir::op_arity(op);
      // Operands from registers, and with a constant second operand.
      for (bool constant : {false, true}) {
        if (constant && arity < 2) continue;
        ir::Code code;
        const Operand a = load(code, kind, 0);
        const Operand b = arity >= 2 ? (constant ? code.constant(-1.5f) : load(code, kind, 1)) : ir::kNone;
        const Operand c = arity >= 3 ? load(code, kind, 2) : ir::kNone;
        const Operand d = code.new_register();
        code.insts.push_back(ir::Inst{op, d, a, b, c, 0, 0});
        store(code, kind, d, 0);
        expect_same_bits(std::move(code), kind, {}, ir::op_name(op));
      }
    }
  }
}

// The caller's rounding mode (an application's) reaches neither tier: runs set round to nearest
// (ir::FlushDenormals), under which the compiled rounding's zeros are +0 as the interpreter's.
TEST_F(CompiledTier, TheCallersRoundingModeDoesNotSplitTheTiers) {
  struct RoundingDown {
    const unsigned saved = _mm_getcsr();
    RoundingDown() { _mm_setcsr((saved & ~0x6000u) | 0x2000u); }
    ~RoundingDown() { _mm_setcsr(saved); }
  } rounding_down;
  for (Stage kind : {Stage::Fragment, Stage::Vertex})
    for (Op op : {Op::Floor, Op::Trunc, Op::Fract, Op::Ceil, Op::Add, Op::Mul}) {
      ir::Code code;
      const Operand a = load(code, kind, 0);
      const Operand b = ir::op_arity(op) == 2 ? load(code, kind, 1) : ir::kNone;
      const Operand d = code.new_register();
      code.insts.push_back(ir::Inst{op, d, a, b, ir::kNone, 0, 0});
      store(code, kind, d, 0);
      expect_same_bits(std::move(code), kind, {}, ir::op_name(op));
    }
}

// pow runs natively (emit_library_ops.h) but for blocks whose lanes need both of its ways (whole
// exponents up to 256, and the others): varying 1 holds the exponents, per lane or one for the
// block, whole or not, and the edges.
Block block_of_exponents(std::mt19937& random) {
  static constexpr uint32_t kEdges[] = {0x00000000, 0x80000000, 0x3F800000, 0xBF800000, 0x40000000, 0x41F80000,
                                        0x42000000, 0x42040000, 0x437F0000, 0x43800000, 0xC3800000, 0x43808000,
                                        0xC3808000, 0x40200000, 0x00000001, 0x80000001, 0x7FC00000, 0x7F800000,
                                        0xFF800000, 0x4F000000, 0xCF000000, 0x4B800000, 0x4F32D05E, 0xC1A00000};
  Block b = random_block(random);
  float* y = &b.varyings[kLanes];
  const int kind = std::uniform_int_distribution<int>(0, 5)(random);
  std::uniform_int_distribution<int> whole(-256, 256);
  std::uniform_real_distribution<float> real(-40.0f, 40.0f);
  const float shared_real = real(random);
  const float edge = std::bit_cast<float>(kEdges[std::uniform_int_distribution<size_t>(0, std::size(kEdges) - 1)(random)]);
  const float shared = static_cast<float>(whole(random));
  for (int l = 0; l < kLanes; ++l) {
    if (kind == 0) y[l] = static_cast<float>(whole(random));  // whole, per lane
    if (kind == 1) y[l] = shared;                             // whole, one for the block
    if (kind == 2) y[l] = edge;
    if (kind == 3) y[l] = l == 5 ? 0.5f : shared;  // lanes of both ways: a call-out
    if (kind == 4) y[l] = real(random);             // 2^(y log2|x|), per lane
    if (kind == 5) y[l] = shared_real;              // and one for the block
  }
  // x: the specials, and magnitudes near 1 whose powers stay finite.
  for (int l = 0; l < kLanes; l += 2)
    b.varyings[static_cast<size_t>(l)] = std::uniform_real_distribution<float>(-1.5f, 1.5f)(random);
  return b;
}

TEST_F(CompiledTier, PowNativelyButForBlocksOfBothWays) {
  for (Stage kind : {Stage::Fragment, Stage::Vertex}) {
    ir::Code code;
    const Operand x = load(code, kind, 0), y = load(code, kind, 1);
    const Operand d = code.new_register();
    code.insts.push_back(ir::Inst{Op::Pow, d, x, y, ir::kNone, 0, 0});
    store(code, kind, d, 0);
    expect_same_bits(std::move(code), kind, {}, "pow", block_of_exponents);
  }
  // Inside a branch (the running lanes take the result), with more values live across it than
  // registers: the call-out keeps them.
  ir::Code code;
  const Operand x = load(code, Stage::Fragment, 0), y = load(code, Stage::Fragment, 1), c = load(code, Stage::Fragment, 2);
  const std::vector<Operand> live = many_values(code, x, c, 32, 0.5f);
  const Operand test = code.new_register(), p = code.new_register();
  code.insts.push_back(ir::Inst{Op::Mov, p, c, ir::kNone, ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::Lt, test, c, code.constant(0.5f), ir::kNone, 0, 0});
  const size_t begin = code.insts.size();
  code.insts.push_back(ir::Inst{Op::IfBegin, ir::kNone, test, ir::kNone, ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::Pow, p, live[3], y, ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::Pow, live[7], x, y, ir::kNone, 0, 0});
  code.insts[begin].i0 = static_cast<int32_t>(code.insts.size());
  code.insts.push_back(ir::Inst{Op::EndIf});
  store(code, Stage::Fragment, sum_of(code, p, live), 0);
  store(code, Stage::Fragment, p, 1);
  store(code, Stage::Fragment, live[7], 2);
  expect_same_bits(std::move(code), Stage::Fragment, {}, "pow in a branch", block_of_exponents);
}

// A loop whose body runs nothing that flushes the registers keeps the values it reads most in
// the same registers from its start to its end (load_resident_values): with more values live
// across it and read in it than registers, a data-dependent break, a branch, and pow in its body whose call-out
// (blocks with a lane the emitted code leaves out) stores the registers and loads them back, the
// same bits as the interpreter.
TEST_F(CompiledTier, LoopResidentValuesKeepTheInterpretersBits) {
  ir::Code code;
  const Operand x = load(code, Stage::Fragment, 0), y = load(code, Stage::Fragment, 1), c = load(code, Stage::Fragment, 2);
  const std::vector<Operand> live = many_values(code, x, c, 32, 0.25f);
  const Operand counter = code.new_register(), test = code.new_register(), acc = code.new_register(),
                other = code.new_register(), p = code.new_register(), t = code.new_register();
  code.insts.push_back(ir::Inst{Op::Mov, counter, code.constant(0.0f), ir::kNone, ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::Mov, acc, x, ir::kNone, ir::kNone, 0, 0});
  const size_t begin = code.insts.size();
  code.insts.push_back(ir::Inst{Op::LoopBegin});
  code.insts.push_back(ir::Inst{Op::Lt, test, counter, code.constant(4.0f), ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::BreakIfNot, ir::kNone, test});
  code.insts.push_back(ir::Inst{Op::Lt, test, acc, code.constant(3.0f), ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::BreakIfNot, ir::kNone, test});  // some lanes leave early
  for (int i = 0; i < 10; ++i)  // read here and below: kept in registers
    code.insts.push_back(ir::Inst{Op::Add, other, other, live[static_cast<size_t>(i)], ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::Pow, p, acc, y, ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::Mad, acc, p, c, live[5], 0, 0});
  code.insts.push_back(ir::Inst{Op::Fract, t, acc, ir::kNone, ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::Lt, test, t, code.constant(0.5f), ir::kNone, 0, 0});
  const size_t branch = code.insts.size();
  code.insts.push_back(ir::Inst{Op::IfBegin, ir::kNone, test});
  code.insts.push_back(ir::Inst{Op::Add, other, other, t, ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::Sin, live[9], acc, ir::kNone, ir::kNone, 0, 0});
  for (int i = 0; i < 32; ++i)  // more values read in the body than registers are left
    code.insts.push_back(ir::Inst{Op::Mad, other, live[static_cast<size_t>(i)], t, other, 0, 0});
  code.insts[branch].i0 = static_cast<int32_t>(code.insts.size());
  code.insts.push_back(ir::Inst{Op::EndIf});
  code.insts.push_back(ir::Inst{Op::ContinuePoint});
  code.insts.push_back(ir::Inst{Op::Add, counter, counter, code.constant(1.0f), ir::kNone, 0, 0});
  const size_t end = code.insts.size();
  code.insts.push_back(ir::Inst{Op::LoopEnd});
  code.insts[begin].i0 = static_cast<int32_t>(end);
  code.insts[end].i0 = static_cast<int32_t>(begin + 1);
  store(code, Stage::Fragment, sum_of(code, acc, live), 0);
  store(code, Stage::Fragment, other, 1);
  store(code, Stage::Fragment, counter, 2);
  store(code, Stage::Fragment, live[9], 3);
  expect_same_bits(std::move(code), Stage::Fragment, {}, "loop-resident values", block_of_exponents);
}

// sin and cos of |x| < 2^17 run natively, a block with a farther, infinite or NaN x in a lane
// calls out: varying 0 holds angles of every size up to the edge, with multiples of pi/4 and
// zeros, denormals and the edge itself.
Block block_of_angles(std::mt19937& random) {
  Block b = random_block(random);
  const int kind = std::uniform_int_distribution<int>(0, 3)(random);
  const float scale = std::array{4.0f, 100.0f, 131071.0f, 8.0f}[static_cast<size_t>(kind)];
  for (int l = 0; l < kLanes; ++l) {
    float& x = b.varyings[static_cast<size_t>(l)];
    x = std::uniform_real_distribution<float>(-scale, scale)(random);
    if (kind == 3) x = static_cast<float>(l - 8) * 0.785398163f;  // near multiples of pi/4
  }
  if (kind == 1) {
    b.varyings[1] = std::bit_cast<float>(0x80000001u);
    b.varyings[2] = -0.0f;
    b.varyings[3] = std::bit_cast<float>(0x47FFFFFFu);  // the largest below 2^17
  }
  if (kind == 2 && std::uniform_int_distribution<int>(0, 1)(random))
    b.varyings[6] = std::bit_cast<float>(kSpecialBits[std::uniform_int_distribution<size_t>(13, 19)(random)]);  // calls out
  return b;
}

// d = op(varying 0) in both stages, over blocks from make_block.
void expect_unary_same_bits(Op op, Block (*make_block)(std::mt19937&)) {
  for (Stage kind : {Stage::Fragment, Stage::Vertex}) {
    ir::Code code;
    const Operand x = load(code, kind, 0);
    const Operand d = code.new_register();
    code.insts.push_back(ir::Inst{op, d, x, ir::kNone, ir::kNone, 0, 0});
    store(code, kind, d, 0);
    expect_same_bits(std::move(code), kind, {}, ir::op_name(op), make_block);
  }
}

TEST_F(CompiledTier, SinAndCosNativelyBelowTwoToTheSeventeenth) {
  expect_unary_same_bits(Op::Sin, block_of_angles);
  expect_unary_same_bits(Op::Cos, block_of_angles);
}

// exp and exp2 run natively for every x: varying 0 holds values across the range where the
// results go from 0 through the denormals (flushed) to infinity.
Block block_of_exponentials(std::mt19937& random) {
  Block b = random_block(random);
  const float scale = std::array{2.0f, 20.0f, 160.0f}[std::uniform_int_distribution<size_t>(0, 2)(random)];
  for (int l = 0; l < kLanes; l += 2)
    b.varyings[static_cast<size_t>(l)] = std::uniform_real_distribution<float>(-scale, scale)(random);
  return b;
}

TEST_F(CompiledTier, ExpAndExp2Natively) {
  expect_unary_same_bits(Op::Exp, block_of_exponentials);
  expect_unary_same_bits(Op::Exp2, block_of_exponentials);
}

TEST_F(CompiledTier, LoadsAndStoresOfEveryKind) {
  ir::Code code;
  const Operand fc = code.new_register(), pc = code.new_register(), ff = code.new_register(), u = code.new_register(),
                g = code.new_register(), i = load(code, Stage::Fragment, 3);
  code.insts.push_back(ir::Inst{Op::LoadFragCoord, fc, ir::kNone, ir::kNone, ir::kNone, 2, 0});
  code.insts.push_back(ir::Inst{Op::LoadPointCoord, pc, ir::kNone, ir::kNone, ir::kNone, 1, 0});
  code.insts.push_back(ir::Inst{Op::LoadFrontFacing, ff, ir::kNone, ir::kNone, ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::LoadUniform, u, ir::kNone, ir::kNone, ir::kNone, 5, 0});
  code.insts.push_back(ir::Inst{Op::GatherUniform, g, i, ir::kNone, ir::kNone, 1, 6});
  store(code, Stage::Fragment, fc, 0);
  store(code, Stage::Fragment, pc, 1);
  store(code, Stage::Fragment, ff, 2);
  const Operand sum = code.new_register();
  code.insts.push_back(ir::Inst{Op::Add, sum, u, g, ir::kNone, 0, 0});
  store(code, Stage::Fragment, sum, 3);
  expect_same_bits(std::move(code), Stage::Fragment, {1, 2, 3, 4, 5, 6.5f, 7, 8, -9}, "loads");
}

// Uniform gathers in a run with one index share its clamping; a gather that writes its own index
// register, or one with another limit, ends the run.
TEST_F(CompiledTier, RunsOfUniformGathersWithOneIndex) {
  ir::Code code;
  const Operand i = load(code, Stage::Fragment, 0);
  Operand g[5];
  for (Operand& r : g) r = code.new_register();
  auto gather = [&](Operand d, int32_t first, int32_t limit) {
    code.insts.push_back(ir::Inst{Op::GatherUniform, d, i, ir::kNone, ir::kNone, first, limit});
  };
  gather(g[0], 0, 7);
  gather(g[1], 1, 7);
  gather(g[2], 2, 7);
  gather(i, 3, 7);  // the index register's new value: an element
  gather(g[3], 4, 7);
  gather(g[4], 5, 3);
  for (int k = 0; k < 3; ++k) {
    const Operand sum = code.new_register();
    code.insts.push_back(ir::Inst{Op::Add, sum, g[k], g[k + 1], ir::kNone, 0, 0});
    store(code, Stage::Fragment, sum, k);
  }
  store(code, Stage::Fragment, g[4], 3);
  expect_same_bits(std::move(code), Stage::Fragment, {0.5f, 3, 7, 1, 2, 6, 4, 5, 2.5f, 0, 1, 3, 9, -1, 2, 8}, "gathers");
}

// Texels made up from the coordinates, the unit and the channel; unit 0 has the 2D block route
// (sample_2d_block), unit 1 only the general one. Counts the lookups of each sample_2d_blocks call.
class MadeUpTextures final : public TextureAccess {
 public:
  static float texel(int unit, int channel, float s, float t) { return s * 0.5f - t * 0.25f + static_cast<float>(4 * unit + channel); }
  void sample(int unit, SamplerKind, const float (*coords)[kLanes], LodMode, const float*, LaneMask,
              float (*out)[kLanes]) const override {
    for (int c = 0; c < 4; ++c)
      for (int l = 0; l < kLanes; ++l) out[c][l] = texel(unit, c, coords[0][l], coords[1][l]);
  }
  bool sample_2d_block(int unit, const float* s, const float* t, LaneMask, float* const out[4]) const override {
    if (unit != 0) return false;
    float texels[4][kLanes];  // (out may be s or t)
    for (int c = 0; c < 4; ++c)
      for (int l = 0; l < kLanes; ++l) texels[c][l] = texel(unit, c, s[l], t[l]);
    for (int c = 0; c < 4; ++c) std::memcpy(out[c], texels[c], sizeof texels[c]);
    return true;
  }
  bool sample_2d_blocks(int unit, int count, const float* const* s, const float* const* t, LaneMask live,
                        float* const (*out)[4]) const override {
    run_counts.push_back(count);
    return TextureAccess::sample_2d_blocks(unit, count, s, t, live, out);
  }
  mutable std::vector<int> run_counts;
};

// Lookups side by side run as one call-out where none reads what an earlier one wrote: a lookup
// that writes an earlier one's coordinate stays in the run, one that reads an earlier one's
// result starts a new run, and a run of several units takes each lookup's own route.
TEST_F(CompiledTier, RunsOfTextureLookupsKeepTheirOrder) {
  ir::Code code;
  const Operand s = load(code, Stage::Fragment, 0), t = load(code, Stage::Fragment, 1);
  const Operand unit0 = code.new_register(), unit1 = code.new_register();
  code.insts.push_back(ir::Inst{Op::LoadUniform, unit0, ir::kNone, ir::kNone, ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::LoadUniform, unit1, ir::kNone, ir::kNone, ir::kNone, 1, 0});
  auto lookup = [&](Operand unit, Operand ls, Operand lt, std::array<Operand, 4> dst) {
    ir::TextureLookup l;
    l.sampler = unit;
    l.coord[0] = ls;
    l.coord[1] = lt;
    for (int c = 0; c < 4; ++c) l.dst[c] = dst[static_cast<size_t>(c)];
    code.textures.push_back(l);
    code.insts.push_back(ir::Inst{Op::Texture, ir::kNone, ir::kNone, ir::kNone, ir::kNone,
                                  static_cast<int32_t>(code.textures.size() - 1), 0});
  };
  auto fresh = [&] {
    std::array<Operand, 4> r;
    for (Operand& o : r) o = code.new_register();
    return r;
  };
  const std::array<Operand, 4> a = fresh(), b = fresh(), c = fresh(), d = fresh(), e = fresh();
  const Operand s_copy = code.new_register();
  code.insts.push_back(ir::Inst{Op::Mov, s_copy, s, ir::kNone, ir::kNone, 0, 0});
  lookup(unit0, s, t, a);
  lookup(unit0, s_copy, t, {b[0], b[1], s, b[3]});  // writes the first one's s: one run of three
  lookup(unit0, t, s_copy, c);
  lookup(unit0, a[0], t, d);  // reads the first one's result: a run of its own and the next
  lookup(unit1, t, a[1], e);  // another unit: each by its own route
  for (int k = 0; k < 4; ++k) {
    Operand sum = code.new_register();
    code.insts.push_back(ir::Inst{Op::Add, sum, a[static_cast<size_t>(k)], k == 2 ? s : b[static_cast<size_t>(k)], ir::kNone, 0, 0});
    for (const auto* r : {&c, &d, &e}) {
      const Operand next = code.new_register();
      code.insts.push_back(ir::Inst{Op::Add, next, sum, (*r)[static_cast<size_t>(k)], ir::kNone, 0, 0});
      sum = next;
    }
    store(code, Stage::Fragment, sum, k);
  }
  const MadeUpTextures textures;
  expect_same_bits(std::move(code), Stage::Fragment, {0, 1}, "texture runs", random_block, &textures);
  // The compiled code's runs of one unit, one for every block it ran: the three lookups.
  EXPECT_EQ(textures.run_counts, std::vector<int>(200, 3));
}

// Sixty values live at once (more than the registers) and a call-out among them.
TEST_F(CompiledTier, SpilledValuesAndCallOutsKeepTheirBits) {
  ir::Code code;
  const Operand a = load(code, Stage::Fragment, 0), b = load(code, Stage::Fragment, 1);
  std::vector<Operand> values;
  Operand previous = a;
  for (int i = 0; i < 60; ++i) {
    const Operand v = code.new_register();
    code.insts.push_back(ir::Inst{Op::Mad, v, previous, b, code.constant(0.25f * static_cast<float>(i)), 0, 0});
    if (i == 30) {
      const Operand s = code.new_register();
      code.insts.push_back(ir::Inst{Op::Sin, s, v, ir::kNone, ir::kNone, 0, 0});
      values.push_back(s);
    }
    values.push_back(v);
    previous = v;
  }
  Operand sum = values.back();
  for (size_t i = 0; i + 1 < values.size(); ++i) {
    const Operand next = code.new_register();
    code.insts.push_back(ir::Inst{i % 2 ? Op::Sub : Op::Add, next, sum, values[i], ir::kNone, 0, 0});
    sum = next;
  }
  store(code, Stage::Fragment, sum, 0);
  store(code, Stage::Fragment, values[5], 1);
  expect_same_bits(std::move(code), Stage::Fragment, {}, "spills");
}

TEST_F(CompiledTier, ConditionalDiscardAndUnwrittenRegisters) {
  ir::Code code;
  const Operand a = load(code, Stage::Fragment, 0);
  const Operand never_written = code.new_register();
  const Operand test = code.new_register();
  code.insts.push_back(ir::Inst{Op::Lt, test, a, code.constant(0.5f), ir::kNone, 0, 0});
  code.insts.push_back(ir::Inst{Op::IfBegin, ir::kNone, test, ir::kNone, ir::kNone, 4, 0});
  code.insts.push_back(ir::Inst{Op::Discard});
  code.insts.push_back(ir::Inst{Op::EndIf});
  const Operand sum = code.new_register();
  code.insts.push_back(ir::Inst{Op::Add, sum, a, never_written, ir::kNone, 0, 0});
  const Operand s = code.new_register();
  code.insts.push_back(ir::Inst{Op::Sin, s, never_written, ir::kNone, ir::kNone, 0, 0});
  store(code, Stage::Fragment, sum, 0);
  store(code, Stage::Fragment, s, 1);
  expect_same_bits(std::move(code), Stage::Fragment, {}, "discard");
}

// Random programs with nested if/else, loops with data-dependent breaks and continues,
// registers indexed per lane,
// functions that return early and discards inside branches: the compiled code's masked writes
// keep what the interpreter keeps.
class RandomProgram {
 public:
  // `registers` values, of which `array` from r3 on form an array indexed per lane.
  RandomProgram(uint32_t seed, int registers, int array) : registers_(registers), array_(array), random_(seed) {}

  ir::Code make() {
    for (int i = 0; i < 3; ++i) load(code_, Stage::Fragment, i);  // r0-r2; r3-r11 start unwritten
    code_.registers = registers_;  // loops' counters come after
    statements(0, false);
    for (int c = 0; c < 4; ++c) store(code_, Stage::Fragment, pick_register(), c);
    return std::move(code_);
  }

 private:
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(random_); }
  Operand pick_register() { return pick(registers_); }
  Operand pick_operand() { return pick(4) == 0 ? code_.constant(static_cast<float>(pick(7)) * 0.5f - 1.0f) : pick_register(); }
  size_t emit(ir::Inst in) {
    code_.insts.push_back(in);
    return code_.insts.size() - 1;
  }

  void statements(int depth, bool in_function, bool in_loop = false) {
    const int count = 2 + pick(5);
    for (int k = 0; k < count; ++k) {
      const int kind = pick(12);
      if (kind < 6 || depth >= 3) {
        value();
      } else if (kind < 8) {
        const size_t begin = emit(ir::Inst{Op::IfBegin, ir::kNone, pick_register()});
        statements(depth + 1, in_function, in_loop);
        if (pick(2)) {
          const size_t otherwise = emit(ir::Inst{Op::Else});
          code_.insts[begin].i0 = static_cast<int32_t>(otherwise);
          statements(depth + 1, in_function, in_loop);
          code_.insts[otherwise].i0 = static_cast<int32_t>(emit(ir::Inst{Op::EndIf}));
        } else {
          code_.insts[begin].i0 = static_cast<int32_t>(emit(ir::Inst{Op::EndIf}));
        }
      } else if (kind == 8 && !in_function) {
        emit(ir::Inst{Op::FuncBegin});
        statements(depth + 1, true, in_loop);
        emit(ir::Inst{Op::FuncEnd});
      } else if (kind == 9) {
        loop(depth, in_function);
      } else if (depth > 0) {
        const int exit = pick(in_loop ? 4 : 2);
        emit(ir::Inst{exit == 0 ? Op::Discard : exit == 1 ? (in_function ? Op::Return : Op::Discard)
                                                          : exit == 2 ? Op::Break : Op::Continue});
      }
    }
  }

  // for (i = 0; i < n && data-dependent exits; ++i) { ... }, n in 0..4.
  void loop(int depth, bool in_function) {
    const Operand counter = code_.new_register(), test = code_.new_register();
    emit(ir::Inst{Op::Mov, counter, code_.constant(0.0f)});
    const size_t begin = emit(ir::Inst{Op::LoopBegin});
    emit(ir::Inst{Op::Lt, test, counter, code_.constant(static_cast<float>(pick(5)))});
    const size_t body = emit(ir::Inst{Op::BreakIfNot, ir::kNone, test});
    if (pick(2)) emit(ir::Inst{Op::BreakIfNot, ir::kNone, pick_register()});
    statements(depth + 1, in_function, true);
    emit(ir::Inst{Op::ContinuePoint});
    emit(ir::Inst{Op::Add, counter, counter, code_.constant(1.0f)});
    const size_t end = emit(ir::Inst{Op::LoopEnd});
    code_.insts[begin].i0 = static_cast<int32_t>(end);
    code_.insts[end].i0 = static_cast<int32_t>(begin + 1);
    (void)body;
  }

  void value() {
    static constexpr Op kOps[] = {Op::Add, Op::Sub, Op::Mul, Op::Div, Op::Min, Op::Max, Op::Floor, Op::Fract,
                                  Op::Mad, Op::Mix, Op::Select, Op::Lt, Op::Ne, Op::Sin, Op::Sqrt, Op::Abs,
                                  Op::Neg, Op::Ddx, Op::Ddy, Op::Mov, Op::Clamp, Op::Step, Op::Pow, Op::Exp2};
    if (pick(8) == 0) {
      if (pick(2)) emit(ir::Inst{Op::Gather, pick_register(), pick_register(), ir::kNone, ir::kNone, 3, array_ - 1});
      else emit(ir::Inst{Op::Scatter, ir::kNone, pick_register(), pick_operand(), ir::kNone, 3, array_ - 1});
      return;
    }
    const Op op = kOps[pick(static_cast<int>(std::size(kOps)))];
    const int arity = op == Op::Mov ? 1 : ir::op_arity(op);
    ir::Inst in{op, pick_register(), pick_register()};
    if (arity >= 2) in.b = pick_operand();
    if (arity >= 3) in.c = pick_operand();
    emit(in);
  }

  int registers_, array_;
  std::mt19937 random_;
  ir::Code code_;
};

// Random programs of seeds 1..count, each run by both tiers.
void expect_random_programs_same_bits(uint32_t count, int registers, int array) {
  for (uint32_t seed = 1; seed <= count; ++seed) {
    RandomProgram program(seed, registers, array);
    const std::string what = "random program (" + std::to_string(registers) + " registers) " + std::to_string(seed);
    expect_same_bits(program.make(), Stage::Fragment, {}, what.c_str());
  }
}

TEST_F(CompiledTier, BranchesLoopsFunctionsAndDiscardsKeepTheInterpretersLanes) {
  expect_random_programs_same_bits(100, 12, 4);
}

// More values than registers, most of them an indexed array: indexed registers are evicted
// and read from their homes.
TEST_F(CompiledTier, RegisterPressureWithIndexedRegisters) { expect_random_programs_same_bits(40, 48, 40); }

TEST_F(CompiledTier, DumpSaysWhichTierRunsEachStage) {
  auto p = link_ok("varying float v; void main() { v = gl_Vertex.x; gl_Position = gl_Vertex; }",
                   "varying float v; void main() { float s = 0.0; for (int i = 0; i < int(v); i++) s += 0.5; "
                   "gl_FragColor = vec4(s); }");
  ASSERT_NE(p, nullptr);
  const std::string ir = dump_ir(*p);
  size_t at = 0, count = 0;
  while ((at = ir.find("; runs compiled (AVX-512)", at)) != std::string::npos) ++count, ++at;
  EXPECT_EQ(count, 2u) << ir;
}

// More registers than the 16 KiB stack buffer holds (256): the homes are on the heap.
TEST_F(CompiledTier, HomesOnTheHeapForManyRegisters) { expect_random_programs_same_bits(10, 300, 40); }

// piglit's variable-indexing tests: an element of a local array of matrices read by two
// uniform indices (a register gather whose array the code wrote just before).
TEST_F(CompiledTier, IndexedLocalMatrixArray) {
  auto p = link_ok("", R"(uniform int index;
uniform int row;
uniform float expect;
void main() {
  mat4 m[3];
  m[0] = mat4(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0, 16.0);
  m[1] = mat4(17.0, 18.0, 19.0, 20.0, 21.0, 22.0, 23.0, 24.0, 25.0, 26.0, 27.0, 28.0, 29.0, 30.0, 31.0, 32.0);
  m[2] = mat4(33.0, 34.0, 35.0, 36.0, 37.0, 38.0, 39.0, 40.0, 41.0, 42.0, 43.0, 44.0, 45.0, 46.0, 47.0, 48.0);
  gl_FragColor = (m[index][1][row] == expect) ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);
})");
  ASSERT_NE(p, nullptr);
  for (int index = 0; index < 3; ++index)
    for (int row = 0; row < 4; ++row) {
      FragmentRun run(*p);
      run.set_uniform(*p, "index", {static_cast<float>(index)});
      run.set_uniform(*p, "row", {static_cast<float>(row)});
      run.set_uniform(*p, "expect", {static_cast<float>(16 * index + 5 + row)});
      run.run(*p);
      EXPECT_EQ(run.block.color[0][1][0], 1.0f) << index << " " << row << "\n" << dump_ir(*p);
    }
}

}  // namespace
}  // namespace pineda::shader::test
