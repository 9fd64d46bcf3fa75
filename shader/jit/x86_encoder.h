// The few x86-64 instructions the shader compiler emits, encoded into a byte buffer: AVX-512
// (EVEX) operations on zmm registers with opmasks, the mask-register (VEX) logic, and the
// general-purpose moves, pushes and calls of a function's frame. Memory operands are always
// [base + disp32].
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pineda::shader::jit {

enum Gpr : uint8_t { rax, rcx, rdx, rbx, rsp, rbp, rsi, rdi, r8, r9, r10, r11, r12, r13, r14, r15 };

struct Mem {
  Gpr base;
  int32_t disp;
};

// vcmpps predicates (imm8), the ones C's comparison operators on floats compile to.
enum class Cmp : uint8_t { Eq = 0x00, Lt = 0x01, Le = 0x02, Unord = 0x03, Neq = 0x04, Ge = 0x0D, Gt = 0x0E };
// vpcmpd / vpcmpud predicates (imm8).
enum class IntCmp : uint8_t { Eq = 0, Lt = 1, Le = 2, Ne = 4, Ge = 5, Gt = 6 };

class X86Encoder {
 public:
  const std::vector<uint8_t>& bytes() const { return bytes_; }

  // zmm forms: d = op(a, b); `mask` k1..k7 merges into d (zero: `zeroing`), 0 is none.
  void vaddps(int d, int a, int b) { evex_rrr(0x58, 1, 0, d, a, b); }
  void vsubps(int d, int a, int b, int mask = 0) { evex_rrr(0x5C, 1, 0, d, a, b, mask); }
  void vmulps(int d, int a, int b) { evex_rrr(0x59, 1, 0, d, a, b); }
  void vdivps(int d, int a, int b) { evex_rrr(0x5E, 1, 0, d, a, b); }
  void vsqrtps(int d, int a) { evex_rrr(0x51, 1, 0, d, 0, a); }
  void vpandd(int d, int a, int b) { evex_rrr(0xDB, 1, 1, d, a, b); }
  void vpxord(int d, int a, int b, int mask = 0) { evex_rrr(0xEF, 1, 1, d, a, b, mask); }
  void vpabsd(int d, int a) { evex_rrr(0x1E, 2, 1, d, 0, a); }
  // k = a & b != 0 per lane, within `mask`.
  void vptestmd(int k, int a, int b, int mask = 0) { evex_rrr(0x27, 2, 1, k, a, b, mask); }
  void vpmovd2m(int k, int a) { evex_rrr(0x39, 2, 2, k, 0, a); }  // k = the lanes' sign bits
  // k = cmp(a, b) on signed (vpcmpd) or unsigned (vpcmpud) lanes, within `mask`.
  void vpcmpd(int k, int a, int b, IntCmp pred, int mask = 0) {
    evex_rrr(0x1F, 3, 1, k, a, b, mask);
    bytes_.push_back(static_cast<uint8_t>(pred));
  }
  void vpcmpud(int k, int a, int b, IntCmp pred, int mask = 0) {
    evex_rrr(0x1E, 3, 1, k, a, b, mask);
    bytes_.push_back(static_cast<uint8_t>(pred));
  }
  // Eight doubles per zmm: d = a * b or a / b (`mask`'s low 8 bits merge).
  void vmulpd(int d, int a, int b, int mask = 0) { evex_rrr(0x59, 1, 1, d, a, b, mask, false, true); }
  void vdivpd(int d, int a, int b, int mask = 0) { evex_rrr(0x5E, 1, 1, d, a, b, mask, false, true); }
  void vaddpd(int d, int a, int b) { evex_rrr(0x58, 1, 1, d, a, b, 0, false, true); }
  void vsubpd(int d, int a, int b) { evex_rrr(0x5C, 1, 1, d, a, b, 0, false, true); }
  void vblendmpd(int d, int mask, int a, int b) { evex_rrr(0x65, 2, 1, d, a, b, mask, false, true); }  // d = mask ? b : a
  // Integer forms on 64-bit lanes.
  void vpaddq(int d, int a, int b) { evex_rrr(0xD4, 1, 1, d, a, b, 0, false, true); }
  void vpxorq(int d, int a, int b, int mask = 0) { evex_rrr(0xEF, 1, 1, d, a, b, mask, false, true); }
  void vptestmq(int k, int a, int b) { evex_rrr(0x27, 2, 1, k, a, b, 0, false, true); }
  void broadcast64(int d, Mem m) { evex_rm(0x19, 2, 1, d, m, true); }  // vbroadcastsd zmm, m64
  void vcvtps2pd(int d, int a) { evex_rrr(0x5A, 1, 0, d, 0, a); }              // zmm d = ymm a's 8 floats
  void vcvtdq2pd(int d, int a) { evex_rrr(0xE6, 1, 2, d, 0, a); }              // zmm d = ymm a's 8 integers
  // k = cmp(a, b) on doubles (the vcmpps predicates).
  void vcmppd(int k, int a, int b, Cmp pred) {
    evex_rrr(0xC2, 1, 1, k, a, b, 0, false, true);
    bytes_.push_back(static_cast<uint8_t>(pred));
  }
  void vmovapd(int d, int a, int mask) { evex_rrr(0x28, 1, 1, d, 0, a, mask, false, true); }  // d = a where mask
  void vpsllq(int d, int a, uint8_t bits) {
    evex_rrr(0x73, 1, 1, 6, d, a, 0, false, true);
    bytes_.push_back(bits);
  }
  void vcvtpd2ps(int d, int a) { evex_rrr(0x5A, 1, 1, d, 0, a, 0, false, true); }  // ymm d = zmm a's 8 doubles
  void vextractf32x8(int d, int a, uint8_t half) {  // ymm d = half `half` of zmm a
    evex_rrr(0x1B, 3, 1, a, 0, d);
    bytes_.push_back(half);
  }
  void vinsertf32x8(int d, int a, int b, uint8_t half) {  // d = a with half `half` from ymm b
    evex_rrr(0x1A, 3, 1, d, a, b);
    bytes_.push_back(half);
  }
  void vcvttps2dq(int d, int a, int mask = 0, bool zeroing = false) { evex_rrr(0x5B, 1, 2, d, 0, a, mask, zeroing); }
  void vcvtdq2ps(int d, int a) { evex_rrr(0x5B, 1, 0, d, 0, a); }
  // imm8 0x09: floor, 0x0B: truncate (and no precision exception).
  void vrndscaleps(int d, int a, uint8_t imm) {
    evex_rrr(0x08, 3, 1, d, 0, a);
    bytes_.push_back(imm);
  }
  void vpminud(int d, int a, int b) { evex_rrr(0x3B, 2, 1, d, a, b); }
  void vpbroadcastd(int d, Gpr s) { evex_rrr(0x7C, 2, 1, d, 0, s); }  // every lane = the low 32 bits of s
  void vpaddd(int d, int a, int b, int mask = 0) { evex_rrr(0xFE, 1, 1, d, a, b, mask); }
  void vpsubd(int d, int a, int b, int mask = 0) { evex_rrr(0xFA, 1, 1, d, a, b, mask); }
  void vpord(int d, int a, int b) { evex_rrr(0xEB, 1, 1, d, a, b); }
  void vpslld(int d, int a, uint8_t bits) {
    evex_rrr(0x72, 1, 1, 6, d, a);
    bytes_.push_back(bits);
  }
  void vpsrld(int d, int a, uint8_t bits) {
    evex_rrr(0x72, 1, 1, 2, d, a);
    bytes_.push_back(bits);
  }
  // d = base[index lane * 4 + disp] in the lanes of mask k (1..7), which it clears.
  void vgatherdps(int d, int mask, Gpr base, int index, int32_t disp) { vsib(0x92, d, mask, base, index, disp); }
  // base[index lane * 4 + disp] = s in the lanes of mask k (1..7), which it clears.
  void vscatterdps(Gpr base, int index, int32_t disp, int mask, int s) { vsib(0xA2, s, mask, base, index, disp); }
  // d = mask ? b : a.
  void vblendmps(int d, int mask, int a, int b) { evex_rrr(0x65, 2, 1, d, a, b, mask); }
  void vmovaps(int d, int a, int mask = 0, bool zeroing = false) { evex_rrr(0x28, 1, 0, d, 0, a, mask, zeroing); }
  // k = cmp(a, b), within `mask` when not 0.
  void vcmpps(int k, int a, int b, Cmp pred, int mask = 0);

  void load(int d, Mem m) { evex_rm(0x10, 1, 0, d, m); }      // vmovups zmm, m512
  void store(Mem m, int s) { evex_rm(0x11, 1, 0, s, m); }     // vmovups m512, zmm
  void broadcast(int d, Mem m) { evex_rm(0x18, 2, 1, d, m); } // vbroadcastss zmm, m32

  // Mask registers (VEX).
  void kmovw_load(int k, Mem m);
  void korw(int k, int a, int b) { vex_k(0x45, 1, k, a, b); }
  void kxorw(int k, int a, int b) { vex_k(0x47, 1, k, a, b); }
  void kxnorw(int k, int a, int b) { vex_k(0x46, 1, k, a, b); }
  void kmovw_to_gpr(Gpr d, int k) { vex_k(0x93, 0, d, 0, k); }  // zero-extended into d's 32 bits
  void kmovw_store(Mem m, int k);
  void kmovw(int k, int a) { vex_k(0x90, 0, k, 0, a); }
  void kandw(int k, int a, int b) { vex_k(0x41, 1, k, a, b); }
  void kandnw(int k, int a, int b) { vex_k(0x42, 1, k, a, b); }  // k = ~a & b
  void kshiftrw(int k, int a, uint8_t bits);

  // General-purpose.
  void push(Gpr r);
  void pop(Gpr r);
  void mov_load(Gpr d, Mem m);   // mov r64, [m]
  void mov_store(Mem m, Gpr s);  // mov [m], r64
  void lea(Gpr d, Mem m);
  void mov_imm(Gpr d, uint64_t value);
  void mov_imm32(Gpr d, uint32_t value);  // zero-extended
  void or_store32(Mem m, Gpr s);          // or [m], s (32 bits)
  void add_rsp(int32_t value);   // add rsp, imm32 (negative: sub)
  void call(Gpr target);
  void mov_store_imm32(Mem m, uint32_t value);  // mov dword [m], imm32
  void dec32(Mem m);                             // dec dword [m]
  // Jumps with 32-bit displacements: the displacement is patched once the target is known
  // (patch_jump), or given for a backward target (jump_back).
  size_t jump_if_zero();           // jz
  size_t jump_if_not_zero();       // jnz
  size_t jump();                   // jmp
  size_t jump_if_not_greater();    // jle
  void jump_back(size_t target);   // jmp
  void patch_jump(size_t site);    // the jump at `site` goes to the current end of the code
  size_t size() const { return bytes_.size(); }
  void kortestw(int a, int b) { vex_k(0x98, 0, a, 0, b); }  // ZF: a | b is zero
  void vzeroupper() { emit({0xC5, 0xF8, 0x77}); }
  void ret() { emit({0xC3}); }

 private:
  void emit(std::initializer_list<uint8_t> b) { bytes_.insert(bytes_.end(), b); }
  void emit32(uint32_t v);
  // map: 1 = 0F, 2 = 0F38, 3 = 0F3A; pp: 0 none, 1 = 66, 2 = F3. `reg` and `vvvv` are register numbers
  // (0-31); rm a register (0-31).
  // `w`: EVEX.W (64-bit elements).
  void evex_rrr(uint8_t opcode, int map, int pp, int reg, int vvvv, int rm, int mask = 0, bool zeroing = false,
                bool w = false);
  void evex_rm(uint8_t opcode, int map, int pp, int reg, Mem m, bool w = false);
  void modrm_mem(int reg, Mem m);
  void vsib(uint8_t opcode, int reg, int mask, Gpr base, int index, int32_t disp);
  void vex_k(uint8_t opcode, int l, int k, int a, int b);
  void rex_w(int reg, Gpr base);

  std::vector<uint8_t> bytes_;
};

}  // namespace pineda::shader::jit
