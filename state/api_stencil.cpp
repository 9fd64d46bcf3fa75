// Stencil function, operations and write mask, per face (GL 2.0 separate stencil), with the
// GL 1.x calls that set both faces and ATI_separate_stencil's names.
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/enum_translate.h"
#include "state/stencil_faces.h"

namespace pineda {
namespace {

bool sets_front(GLenum face) { return face == GL_FRONT || face == GL_FRONT_AND_BACK; }
bool sets_back(GLenum face) { return face == GL_BACK || face == GL_FRONT_AND_BACK; }
bool is_face(GLenum face) { return sets_front(face) || sets_back(face); }

// GL 1.1 4.1.4: ref is clamped to [0, 2^s - 1]; Pineda's stencil buffers have 8 bits.
void set_func(raster::StencilFace& face, raster::CompareFunc f, GLint ref, GLuint mask) {
  face.func = f;
  face.ref = std::clamp(ref, 0, 255);
  face.value_mask = static_cast<uint8_t>(mask);
}

void set_ops(raster::StencilFace& face, raster::StencilOp fail, raster::StencilOp zfail, raster::StencilOp zpass) {
  face.fail = fail;
  face.depth_fail = zfail;
  face.depth_pass = zpass;
}

}  // namespace

bool query_stencil_back(Context& ctx, unsigned pname, GetValues& out) {
  const StencilBackValues& b = ctx.stencil_back_values;
  switch (pname) {
    case GL_STENCIL_BACK_FUNC: out = get_enums({double(b.func)}); return true;
    case GL_STENCIL_BACK_REF: out = get_ints({double(ctx.draw_state.stencil_back.ref)}); return true;
    case GL_STENCIL_BACK_VALUE_MASK: out = get_ints({double(b.value_mask)}); return true;
    case GL_STENCIL_BACK_WRITEMASK: out = get_ints({double(b.write_mask)}); return true;
    case GL_STENCIL_BACK_FAIL: out = get_enums({double(b.fail)}); return true;
    case GL_STENCIL_BACK_PASS_DEPTH_FAIL: out = get_enums({double(b.zfail)}); return true;
    case GL_STENCIL_BACK_PASS_DEPTH_PASS: out = get_enums({double(b.zpass)}); return true;
    default: return false;
  }
}

}  // namespace pineda

namespace pineda::gl {

void StencilFuncSeparate(Context& ctx, GLenum face, GLenum func, GLint ref, GLuint mask) {
  raster::CompareFunc f;
  if (!is_face(face)) return ctx.record_error(GL_INVALID_ENUM, "face is not GL_FRONT, GL_BACK or GL_FRONT_AND_BACK");
  if (!to_compare_func(func, f)) return ctx.record_error(GL_INVALID_ENUM, "func is not a comparison function");
  if (sets_front(face)) {
    ctx.stencil_func = func;
    ctx.stencil_value_mask = mask;
    set_func(ctx.draw_state.stencil_front, f, ref, mask);
  }
  if (sets_back(face)) {
    ctx.stencil_back_values.func = func;
    ctx.stencil_back_values.value_mask = mask;
    set_func(ctx.draw_state.stencil_back, f, ref, mask);
  }
}

void StencilOpSeparate(Context& ctx, GLenum face, GLenum fail, GLenum zfail, GLenum zpass) {
  raster::StencilOp f, zf, zp;
  if (!is_face(face)) return ctx.record_error(GL_INVALID_ENUM, "face is not GL_FRONT, GL_BACK or GL_FRONT_AND_BACK");
  if (!to_stencil_op(fail, f) || !to_stencil_op(zfail, zf) || !to_stencil_op(zpass, zp))
    return ctx.record_error(GL_INVALID_ENUM, "sfail, dpfail or dppass is not a stencil operation");
  if (sets_front(face)) {
    ctx.stencil_fail = fail;
    ctx.stencil_zfail = zfail;
    ctx.stencil_zpass = zpass;
    set_ops(ctx.draw_state.stencil_front, f, zf, zp);
  }
  if (sets_back(face)) {
    StencilBackValues& b = ctx.stencil_back_values;
    b.fail = fail;
    b.zfail = zfail;
    b.zpass = zpass;
    set_ops(ctx.draw_state.stencil_back, f, zf, zp);
  }
}

void StencilMaskSeparate(Context& ctx, GLenum face, GLuint mask) {
  if (!is_face(face)) return ctx.record_error(GL_INVALID_ENUM, "face is not GL_FRONT, GL_BACK or GL_FRONT_AND_BACK");
  if (sets_front(face)) {
    ctx.stencil_write_mask = mask;
    ctx.draw_state.stencil_front.write_mask = static_cast<uint8_t>(mask);
  }
  if (sets_back(face)) {
    ctx.stencil_back_values.write_mask = mask;
    ctx.draw_state.stencil_back.write_mask = static_cast<uint8_t>(mask);
  }
}

void StencilFunc(Context& ctx, GLenum func, GLint ref, GLuint mask) {
  StencilFuncSeparate(ctx, GL_FRONT_AND_BACK, func, ref, mask);
}
void StencilOp(Context& ctx, GLenum fail, GLenum zfail, GLenum zpass) {
  StencilOpSeparate(ctx, GL_FRONT_AND_BACK, fail, zfail, zpass);
}
void StencilMask(Context& ctx, GLuint mask) { StencilMaskSeparate(ctx, GL_FRONT_AND_BACK, mask); }

// ATI_separate_stencil: one call sets both faces' functions, with one reference and mask.
void StencilFuncSeparateATI(Context& ctx, GLenum front_func, GLenum back_func, GLint ref, GLuint mask) {
  raster::CompareFunc f;
  if (!to_compare_func(front_func, f) || !to_compare_func(back_func, f))
    return ctx.record_error(GL_INVALID_ENUM, "frontfunc or backfunc is not a comparison function");
  StencilFuncSeparate(ctx, GL_FRONT, front_func, ref, mask);
  StencilFuncSeparate(ctx, GL_BACK, back_func, ref, mask);
}
void StencilOpSeparateATI(Context& ctx, GLenum face, GLenum fail, GLenum zfail, GLenum zpass) {
  StencilOpSeparate(ctx, face, fail, zfail, zpass);
}

}  // namespace pineda::gl
