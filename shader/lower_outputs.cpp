// Vertex and fragment outputs at the end of a stage.
#include "shader/lowerer.h"

#include <algorithm>

namespace pineda::shader::lowering {

// The epilogue: vertex outputs to their output floats (varyings by name, the built-in
// colours to the fragment inputs they feed), fragment outputs to the block.
void Lowerer::route_outputs() {
  if (stage_ == Stage::Fragment) {
    for (const OutputVar& o : outputs_) {
      if (o.name == "gl_FragColor") {
        iface_.draw_buffers = std::max(iface_.draw_buffers, 1);
        iface_.broadcasts_color = true;
        for (int c = 0; c < 4; ++c)
          code_.insts.push_back(ir::Inst{Op::StoreColor, kNone, o.reg + c, kNone, kNone, c, 1});
      } else if (o.name == "gl_FragData") {
        for (int b = 0; b < iface_.draw_buffers && b < o.type.array; ++b)
          for (int c = 0; c < 4; ++c)
            code_.insts.push_back(ir::Inst{Op::StoreColor, kNone, o.reg + b * 4 + c, kNone, kNone, b * 4 + c, 0});
      } else if (o.name == "gl_FragDepth") {
        iface_.writes_depth = true;
        code_.insts.push_back(ir::Inst{Op::StoreDepth, kNone, o.reg});
      }
    }
    return;
  }
  std::vector<std::pair<int, Operand>> stores;  // output float, register
  Operand position_reg = kNone;
  bool writes_clip_vertex = false;
  for (const OutputVar& o : outputs_) {
    auto store_range = [&](int first_float, int reg, int n) {
      for (int c = 0; c < n; ++c) stores.emplace_back(kOutFirstVarying + first_float + c, reg + c);
    };
    if (o.name == "gl_Position") {
      for (int c = 0; c < 4; ++c) stores.emplace_back(kOutPosition + c, o.reg + c);
      position_reg = o.reg;
      continue;
    }
    if (o.name == "gl_PointSize") {
      iface_.writes_point_size = true;
      stores.emplace_back(kOutPointSize, o.reg);
      continue;
    }
    if (o.name == "gl_ClipVertex") {
      for (int c = 0; c < 4; ++c) stores.emplace_back(kOutClipVertex + c, o.reg + c);
      writes_clip_vertex = true;
      continue;
    }
    std::string target = o.name;
    bool back = false;
    // GL 2.0 section 2.14.7: the colours a vertex shader writes are clamped to [0, 1] (there is
    // no ARB_color_buffer_float to turn that off).
    auto clamped_colour = [&](int first_float, int n) {
      for (int c = 0; c < n; ++c)
        stores.emplace_back(kOutFirstVarying + first_float + c, emit(Op::Clamp, o.reg + c, k(0.0f), k(1.0f)));
    };
    if (o.name == "gl_FrontColor") target = "gl_Color";
    else if (o.name == "gl_BackColor") target = "gl_Color", back = true;
    else if (o.name == "gl_FrontSecondaryColor") target = "gl_SecondaryColor";
    else if (o.name == "gl_BackSecondaryColor") target = "gl_SecondaryColor", back = true;
    VaryingVar* v = iface_.find_varying(target);
    if (!v && !iface_.has_fragment_shader && starts_with_gl(target)) {
      VarType t = o.type;
      if (target == "gl_Color" || target == "gl_SecondaryColor") t = VarType::vec(4);
      v = &iface_.add_varying(target, t);
    }
    if (!v) continue;  // not read by the fragment shader
    if (back) {
      if (v->back_offset < 0) {
        v->back_offset = iface_.varying_floats;
        iface_.varying_floats += 4;
      }
      clamped_colour(v->back_offset, 4);
      continue;
    }
    if (!starts_with_gl(target) && !(v->type == o.type))
      fail("error: vertex shader output `" + o.name + "' declared as type `" + type_name(o.type) +
           "', but fragment shader input declared as type `" + type_name(v->type) + "'\n");
    const int n = std::min(o.type.size(), v->type.size());
    if (target != o.name) clamped_colour(v->offset, n);  // gl_FrontColor, gl_FrontSecondaryColor
    else store_range(v->offset, o.reg, n);
  }
  // GLSL 1.10 and 1.20 (as Mesa, which only warns for GLSL ES): the vertex shader writes it.
  if (position_reg == kNone && !es_) fail("error: vertex shader does not write to `gl_Position'\n");
  if (!writes_clip_vertex && position_reg != kNone)
    for (int c = 0; c < 4; ++c) stores.emplace_back(kOutClipVertex + c, position_reg + c);
  std::vector<bool> written(kOutFirstVarying + iface_.varying_floats, false);
  for (auto& [index, reg] : stores) {
    written[index] = true;
    code_.insts.push_back(ir::Inst{Op::StoreOutput, kNone, reg, kNone, kNone, index});
  }
  for (size_t i = 0; i < written.size(); ++i)
    if (!written[i]) code_.insts.push_back(ir::Inst{Op::StoreOutput, kNone, k(0.0f), kNone, kNone, static_cast<int>(i)});
  // Fragment inputs that the vertex shader does not declare.
  if (iface_.has_fragment_shader)
    for (const VaryingVar& v : iface_.varyings) {
      if (starts_with_gl(v.name)) continue;
      auto d = declared_outputs_.find(v.name);
      const bool written = std::any_of(outputs_.begin(), outputs_.end(), [&](const OutputVar& o) { return o.name == v.name; });
      // Desktop GLSL: declared and never used is not written either (as Mesa); in GLSL ES the
      // value is undefined.
      if (d == declared_outputs_.end() || (!written && !es_))
        fail("error: fragment shader varying " + v.name + " not written by vertex shader\n");
      if (!(d->second == v.type))
        fail("error: vertex shader output `" + v.name + "' declared as type `" + type_name(d->second) +
             "', but fragment shader input declared as type `" + type_name(v.type) + "'\n");
    }
}

}  // namespace pineda::shader::lowering
