#include "shader/jit/x86_encoder.h"

namespace pineda::shader::jit {

namespace {
constexpr uint8_t kLength512 = 2 << 5;  // EVEX.L'L
uint8_t inverted_bit(int value, int bit) { return static_cast<uint8_t>(((value >> bit) & 1) ^ 1); }
}  // namespace

void X86Encoder::emit32(uint32_t v) {
  for (int i = 0; i < 4; ++i) bytes_.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

void X86Encoder::modrm_mem(int reg, Mem m) {
  bytes_.push_back(static_cast<uint8_t>(0x80 | (reg & 7) << 3 | (m.base & 7)));  // mod 10: disp32
  if ((m.base & 7) == 4) bytes_.push_back(0x24);                                 // rsp, r12: SIB, no index
  emit32(static_cast<uint32_t>(m.disp));
}

void X86Encoder::evex_rrr(uint8_t opcode, int map, int pp, int reg, int vvvv, int rm, int mask, bool zeroing, bool w) {
  const uint8_t p0 = static_cast<uint8_t>(inverted_bit(reg, 3) << 7 | inverted_bit(rm, 4) << 6 | inverted_bit(rm, 3) << 5 |
                                          inverted_bit(reg, 4) << 4 | map);
  const uint8_t p1 = static_cast<uint8_t>((w ? 0x80 : 0) | (~vvvv & 15) << 3 | 1 << 2 | pp);
  const uint8_t p2 = static_cast<uint8_t>((zeroing ? 0x80 : 0) | kLength512 | inverted_bit(vvvv, 4) << 3 | (mask & 7));
  emit({0x62, p0, p1, p2, opcode, static_cast<uint8_t>(0xC0 | (reg & 7) << 3 | (rm & 7))});
}

void X86Encoder::evex_rm(uint8_t opcode, int map, int pp, int reg, Mem m, bool w) {
  const uint8_t p0 = static_cast<uint8_t>(inverted_bit(reg, 3) << 7 | 1 << 6 | inverted_bit(m.base, 3) << 5 |
                                          inverted_bit(reg, 4) << 4 | map);
  const uint8_t p1 = static_cast<uint8_t>((w ? 0x80 : 0) | 15 << 3 | 1 << 2 | pp);
  const uint8_t p2 = static_cast<uint8_t>(kLength512 | 1 << 3);
  emit({0x62, p0, p1, p2, opcode});
  modrm_mem(reg, m);
}

void X86Encoder::vcmpps(int k, int a, int b, Cmp pred, int mask) {
  evex_rrr(0xC2, 1, 0, k, a, b, mask);
  bytes_.push_back(static_cast<uint8_t>(pred));
}

void X86Encoder::vex_k(uint8_t opcode, int l, int k, int a, int b) {
  emit({0xC4, 0xE1, static_cast<uint8_t>((~a & 15) << 3 | l << 2), opcode,
        static_cast<uint8_t>(0xC0 | (k & 7) << 3 | (b & 7))});
}

void X86Encoder::kshiftrw(int k, int a, uint8_t bits) {  // VEX.L0.66.0F3A.W1 30 /r ib
  emit({0xC4, 0xE3, 0xF9, 0x30, static_cast<uint8_t>(0xC0 | (k & 7) << 3 | (a & 7)), bits});
}

void X86Encoder::vsib(uint8_t opcode, int reg, int mask, Gpr base, int index, int32_t disp) {
  const uint8_t p0 = static_cast<uint8_t>(inverted_bit(reg, 3) << 7 | inverted_bit(index, 3) << 6 | inverted_bit(base, 3) << 5 |
                                          inverted_bit(reg, 4) << 4 | 2);
  const uint8_t p1 = static_cast<uint8_t>(15 << 3 | 1 << 2 | 1);
  const uint8_t p2 = static_cast<uint8_t>(kLength512 | inverted_bit(index, 4) << 3 | (mask & 7));
  emit({0x62, p0, p1, p2, opcode, static_cast<uint8_t>(0x80 | (reg & 7) << 3 | 4),
        static_cast<uint8_t>(2 << 6 | (index & 7) << 3 | (base & 7))});  // scale 4
  emit32(static_cast<uint32_t>(disp));
}

void X86Encoder::kmovw_load(int k, Mem m) {
  emit({0xC4, static_cast<uint8_t>(0xC0 | inverted_bit(m.base, 3) << 5 | 1), 0x78, 0x90});
  modrm_mem(k, m);
}

void X86Encoder::kmovw_store(Mem m, int k) {
  emit({0xC4, static_cast<uint8_t>(0xC0 | inverted_bit(m.base, 3) << 5 | 1), 0x78, 0x91});
  modrm_mem(k, m);
}

void X86Encoder::push(Gpr r) {
  if (r >= 8) bytes_.push_back(0x41);
  bytes_.push_back(static_cast<uint8_t>(0x50 + (r & 7)));
}

void X86Encoder::pop(Gpr r) {
  if (r >= 8) bytes_.push_back(0x41);
  bytes_.push_back(static_cast<uint8_t>(0x58 + (r & 7)));
}

void X86Encoder::rex_w(int reg, Gpr base) {
  bytes_.push_back(static_cast<uint8_t>(0x48 | ((reg >> 3) & 1) << 2 | ((base >> 3) & 1)));
}

void X86Encoder::mov_load(Gpr d, Mem m) {
  rex_w(d, m.base);
  bytes_.push_back(0x8B);
  modrm_mem(d, m);
}

void X86Encoder::mov_store(Mem m, Gpr s) {
  rex_w(s, m.base);
  bytes_.push_back(0x89);
  modrm_mem(s, m);
}

void X86Encoder::lea(Gpr d, Mem m) {
  rex_w(d, m.base);
  bytes_.push_back(0x8D);
  modrm_mem(d, m);
}

void X86Encoder::mov_imm(Gpr d, uint64_t value) {
  bytes_.push_back(static_cast<uint8_t>(0x48 | ((d >> 3) & 1)));
  bytes_.push_back(static_cast<uint8_t>(0xB8 + (d & 7)));
  for (int i = 0; i < 8; ++i) bytes_.push_back(static_cast<uint8_t>(value >> (8 * i)));
}

void X86Encoder::mov_imm32(Gpr d, uint32_t value) {
  if (d >= 8) bytes_.push_back(0x41);
  bytes_.push_back(static_cast<uint8_t>(0xB8 + (d & 7)));
  emit32(value);
}

void X86Encoder::or_store32(Mem m, Gpr s) {
  if (s >= 8 || m.base >= 8) bytes_.push_back(static_cast<uint8_t>(0x40 | ((s >> 3) & 1) << 2 | ((m.base >> 3) & 1)));
  bytes_.push_back(0x09);
  modrm_mem(s, m);
}

void X86Encoder::mov_store_imm32(Mem m, uint32_t value) {
  if (m.base >= 8) bytes_.push_back(0x41);
  bytes_.push_back(0xC7);
  modrm_mem(0, m);
  emit32(value);
}

void X86Encoder::dec32(Mem m) {
  if (m.base >= 8) bytes_.push_back(0x41);
  bytes_.push_back(0xFF);
  modrm_mem(1, m);
}

size_t X86Encoder::jump_if_zero() {
  emit({0x0F, 0x84});
  emit32(0);
  return bytes_.size();
}

size_t X86Encoder::jump_if_not_zero() {
  emit({0x0F, 0x85});
  emit32(0);
  return bytes_.size();
}

size_t X86Encoder::jump() {
  bytes_.push_back(0xE9);
  emit32(0);
  return bytes_.size();
}

size_t X86Encoder::jump_if_not_greater() {
  emit({0x0F, 0x8E});
  emit32(0);
  return bytes_.size();
}

void X86Encoder::jump_back(size_t target) {
  bytes_.push_back(0xE9);
  emit32(static_cast<uint32_t>(static_cast<int64_t>(target) - static_cast<int64_t>(bytes_.size() + 4)));
}

void X86Encoder::patch_jump(size_t site) {
  const auto displacement = static_cast<uint32_t>(static_cast<int64_t>(bytes_.size()) - static_cast<int64_t>(site));
  for (int i = 0; i < 4; ++i) bytes_[site - 4 + static_cast<size_t>(i)] = static_cast<uint8_t>(displacement >> (8 * i));
}

void X86Encoder::add_rsp(int32_t value) {
  emit({0x48, 0x81, 0xC4});
  emit32(static_cast<uint32_t>(value));
}

void X86Encoder::call(Gpr target) {
  if (target >= 8) bytes_.push_back(0x41);
  emit({0xFF, static_cast<uint8_t>(0xD0 | (target & 7))});
}

}  // namespace pineda::shader::jit
