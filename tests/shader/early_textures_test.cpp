// move_texture_lookups_early (shader/early_textures.h) on hand-made IR: which instructions a
// lookup and its coordinate arithmetic rise above, and where they must stop.
#include <gtest/gtest.h>

#include <vector>

#include "shader/early_textures.h"

namespace pineda::shader {
namespace {

using ir::Inst;
using ir::Op;

// A 2D lookup of unit register `unit` at (s, t) into dst..dst+3.
Inst lookup(ir::Code& code, int unit, int s, int t, int dst) {
  ir::TextureLookup l;
  l.sampler = unit;
  l.coord[0] = s;
  l.coord[1] = t;
  for (int c = 0; c < 4; ++c) l.dst[c] = dst + c;
  code.textures.push_back(l);
  return Inst{Op::Texture, ir::kNone, ir::kNone, ir::kNone, ir::kNone, static_cast<int32_t>(code.textures.size() - 1)};
}

std::vector<Op> ops(const ir::Code& code) {
  std::vector<Op> out;
  for (const Inst& in : code.insts) out.push_back(in.op);
  return out;
}

// r0, r1: coordinates; r2: the unit; a 3-tap kernel in which each tap's result is summed
// before the next tap's offset is computed.
ir::Code three_taps() {
  ir::Code code;
  code.registers = 40;
  const int k = code.constant(0.5f);
  code.insts.push_back({Op::LoadVarying, 0, ir::kNone, ir::kNone, ir::kNone, 0});
  code.insts.push_back({Op::LoadVarying, 1, ir::kNone, ir::kNone, ir::kNone, 1});
  code.insts.push_back({Op::LoadUniform, 2, ir::kNone, ir::kNone, ir::kNone, 0});
  code.insts.push_back(lookup(code, 2, 0, 1, 10));
  code.insts.push_back({Op::Mul, 30, 10, k});
  code.insts.push_back({Op::Add, 3, 0, k});  // tap 2's s
  code.insts.push_back(lookup(code, 2, 3, 1, 14));
  code.insts.push_back({Op::Mad, 31, 14, k, 30});
  code.insts.push_back({Op::Sub, 4, 0, k});  // tap 3's s
  code.insts.push_back(lookup(code, 2, 4, 1, 18));
  code.insts.push_back({Op::Mad, 32, 18, k, 31});
  code.insts.push_back({Op::StoreColor, ir::kNone, 32, ir::kNone, ir::kNone, 0});
  return code;
}

TEST(EarlyTextures, KernelTapsEndUpSideBySideAfterTheirCoordinates) {
  ir::Code code = three_taps();
  ASSERT_TRUE(move_texture_lookups_early(code));
  // The offsets rise to just after r0's load (in their order), the lookups to just after the unit.
  const std::vector<Op> expected = {Op::LoadVarying, Op::Add,     Op::Sub,     Op::LoadVarying, Op::LoadUniform,
                                    Op::Texture,     Op::Texture, Op::Texture, Op::Mul,         Op::Mad,
                                    Op::Mad,         Op::StoreColor};
  EXPECT_EQ(ops(code), expected);
  // The lookups keep their order (texture index 0, 1, 2) and the sums theirs.
  EXPECT_EQ(code.insts[5].i0, 0);
  EXPECT_EQ(code.insts[6].i0, 1);
  EXPECT_EQ(code.insts[7].i0, 2);
  EXPECT_EQ(code.insts[1].d, 3);
  EXPECT_EQ(code.insts[2].d, 4);
  EXPECT_EQ(code.insts[8].d, 30);
  EXPECT_EQ(code.insts[9].d, 31);
  EXPECT_EQ(code.insts[10].d, 32);
  EXPECT_FALSE(move_texture_lookups_early(code));  // nothing left to move
}

TEST(EarlyTextures, ALookupStaysBelowWhatReadsOrWritesItsResultOrWritesItsCoordinates) {
  ir::Code code = three_taps();
  // Tap 2's result register is read before tap 2 (an older value of r14): tap 2 stays below it.
  code.insts.insert(code.insts.begin() + 6, Inst{Op::Mov, 35, 14});
  // Tap 3's t is rewritten before it: tap 3 stays below the write.
  code.insts.insert(code.insts.begin() + 9, Inst{Op::Mov, 1, 0});
  move_texture_lookups_early(code);
  auto position = [&](int texture) {
    for (size_t i = 0; i < code.insts.size(); ++i)
      if (code.insts[i].op == Op::Texture && code.insts[i].i0 == texture) return static_cast<int>(i);
    return -1;
  };
  auto position_of_move = [&](int reg) {
    for (size_t i = 0; i < code.insts.size(); ++i)
      if (code.insts[i].op == Op::Mov && code.insts[i].d == reg) return static_cast<int>(i);
    return -1;
  };
  EXPECT_GT(position(1), position_of_move(35));
  EXPECT_GT(position(2), position_of_move(1));
  EXPECT_LT(position(0), position(1));
  EXPECT_LT(position(1), position(2));
}

// Two lookups with arithmetic between them that neither reads the first one's result nor writes
// its operands: that arithmetic feeds the second lookup through two steps (Sin, then Mul), so it
// rises above the first lookup as far as its operands allow, and the lookups stand side by side.
// A third after a use of the second's result rises to just below the second.
TEST(EarlyTextures, LookupsMoveDownToTheNextLookupOfTheirStretch) {
  ir::Code code;
  code.registers = 40;
  const int k = code.constant(2.0f);
  code.insts.push_back({Op::LoadVarying, 0, ir::kNone, ir::kNone, ir::kNone, 0});
  code.insts.push_back({Op::LoadUniform, 2, ir::kNone, ir::kNone, ir::kNone, 0});
  code.insts.push_back(lookup(code, 2, 0, 0, 10));
  code.insts.push_back({Op::Sin, 3, 0});           // feeds the second lookup through the Mul:
  code.insts.push_back({Op::Mul, 30, 3, k});       // both rise to just after the varying
  code.insts.push_back(lookup(code, 2, 0, 30, 14));
  code.insts.push_back({Op::Mul, 31, 14, k});      // reads the second one's result
  code.insts.push_back(lookup(code, 2, 0, 0, 18));
  code.insts.push_back({Op::Add, 32, 10, 31});
  code.insts.push_back({Op::Add, 33, 32, 18});
  code.insts.push_back({Op::StoreColor, ir::kNone, 33, ir::kNone, ir::kNone, 0});
  ASSERT_TRUE(move_texture_lookups_early(code));
  const std::vector<Op> expected = {Op::LoadVarying, Op::Sin, Op::Mul, Op::LoadUniform, Op::Texture, Op::Texture,
                                    Op::Texture, Op::Mul, Op::Add, Op::Add, Op::StoreColor};
  EXPECT_EQ(ops(code), expected);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(code.insts[4 + static_cast<size_t>(i)].i0, i);  // in their order
}

TEST(EarlyTextures, LookupsDoNotLeaveTheirBranch) {
  ir::Code code;
  code.registers = 40;
  code.insts.push_back({Op::LoadVarying, 0, ir::kNone, ir::kNone, ir::kNone, 0});
  code.insts.push_back({Op::LoadUniform, 2, ir::kNone, ir::kNone, ir::kNone, 0});
  code.insts.push_back({Op::IfBegin, ir::kNone, 0});
  code.insts.push_back({Op::Mul, 5, 0, 0});
  code.insts.push_back(lookup(code, 2, 0, 0, 10));
  code.insts.push_back({Op::EndIf});
  ASSERT_TRUE(move_texture_lookups_early(code));
  const std::vector<Op> expected = {Op::LoadVarying, Op::LoadUniform, Op::IfBegin, Op::Texture, Op::Mul, Op::EndIf};
  EXPECT_EQ(ops(code), expected);
}

}  // namespace
}  // namespace pineda::shader
