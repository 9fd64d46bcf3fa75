// The ARB_shader_objects / ARB_vertex_shader names of GL 2.0 functions that display lists
// compile (glUseProgramObjectARB, glUniform*ARB, glVertexAttrib*ARB): each its own entry point,
// so that a compiled call replays under its own name; each does what the GL 2.0 function does.
#include "glapi/gl_entry_points.h"

namespace pineda::gl {

void UseProgramObjectARB(Context& ctx, GLhandleARB programObj) { UseProgram(ctx, programObj); }
void Uniform1fARB(Context& ctx, GLint location, GLfloat v0) { Uniform1f(ctx, location, v0); }
void Uniform1iARB(Context& ctx, GLint location, GLint v0) { Uniform1i(ctx, location, v0); }
void Uniform2fARB(Context& ctx, GLint location, GLfloat v0, GLfloat v1) { Uniform2f(ctx, location, v0, v1); }
void Uniform2iARB(Context& ctx, GLint location, GLint v0, GLint v1) { Uniform2i(ctx, location, v0, v1); }
void Uniform3fARB(Context& ctx, GLint location, GLfloat v0, GLfloat v1, GLfloat v2) { Uniform3f(ctx, location, v0, v1, v2); }
void Uniform3iARB(Context& ctx, GLint location, GLint v0, GLint v1, GLint v2) { Uniform3i(ctx, location, v0, v1, v2); }
void Uniform4fARB(Context& ctx, GLint location, GLfloat v0, GLfloat v1, GLfloat v2, GLfloat v3) { Uniform4f(ctx, location, v0, v1, v2, v3); }
void Uniform4iARB(Context& ctx, GLint location, GLint v0, GLint v1, GLint v2, GLint v3) { Uniform4i(ctx, location, v0, v1, v2, v3); }
void VertexAttrib1sARB(Context& ctx, GLuint index, GLshort x) { VertexAttrib1s(ctx, index, x); }
void VertexAttrib1svARB(Context& ctx, GLuint index, const GLshort * v) { VertexAttrib1sv(ctx, index, v); }
void VertexAttrib1fARB(Context& ctx, GLuint index, GLfloat x) { VertexAttrib1f(ctx, index, x); }
void VertexAttrib1fvARB(Context& ctx, GLuint index, const GLfloat * v) { VertexAttrib1fv(ctx, index, v); }
void VertexAttrib1dARB(Context& ctx, GLuint index, GLdouble x) { VertexAttrib1d(ctx, index, x); }
void VertexAttrib1dvARB(Context& ctx, GLuint index, const GLdouble * v) { VertexAttrib1dv(ctx, index, v); }
void VertexAttrib2sARB(Context& ctx, GLuint index, GLshort x, GLshort y) { VertexAttrib2s(ctx, index, x, y); }
void VertexAttrib2svARB(Context& ctx, GLuint index, const GLshort * v) { VertexAttrib2sv(ctx, index, v); }
void VertexAttrib2fARB(Context& ctx, GLuint index, GLfloat x, GLfloat y) { VertexAttrib2f(ctx, index, x, y); }
void VertexAttrib2fvARB(Context& ctx, GLuint index, const GLfloat * v) { VertexAttrib2fv(ctx, index, v); }
void VertexAttrib2dARB(Context& ctx, GLuint index, GLdouble x, GLdouble y) { VertexAttrib2d(ctx, index, x, y); }
void VertexAttrib2dvARB(Context& ctx, GLuint index, const GLdouble * v) { VertexAttrib2dv(ctx, index, v); }
void VertexAttrib3sARB(Context& ctx, GLuint index, GLshort x, GLshort y, GLshort z) { VertexAttrib3s(ctx, index, x, y, z); }
void VertexAttrib3svARB(Context& ctx, GLuint index, const GLshort * v) { VertexAttrib3sv(ctx, index, v); }
void VertexAttrib3fARB(Context& ctx, GLuint index, GLfloat x, GLfloat y, GLfloat z) { VertexAttrib3f(ctx, index, x, y, z); }
void VertexAttrib3fvARB(Context& ctx, GLuint index, const GLfloat * v) { VertexAttrib3fv(ctx, index, v); }
void VertexAttrib3dARB(Context& ctx, GLuint index, GLdouble x, GLdouble y, GLdouble z) { VertexAttrib3d(ctx, index, x, y, z); }
void VertexAttrib3dvARB(Context& ctx, GLuint index, const GLdouble * v) { VertexAttrib3dv(ctx, index, v); }
void VertexAttrib4sARB(Context& ctx, GLuint index, GLshort x, GLshort y, GLshort z, GLshort w) { VertexAttrib4s(ctx, index, x, y, z, w); }
void VertexAttrib4svARB(Context& ctx, GLuint index, const GLshort * v) { VertexAttrib4sv(ctx, index, v); }
void VertexAttrib4fARB(Context& ctx, GLuint index, GLfloat x, GLfloat y, GLfloat z, GLfloat w) { VertexAttrib4f(ctx, index, x, y, z, w); }
void VertexAttrib4fvARB(Context& ctx, GLuint index, const GLfloat * v) { VertexAttrib4fv(ctx, index, v); }
void VertexAttrib4dARB(Context& ctx, GLuint index, GLdouble x, GLdouble y, GLdouble z, GLdouble w) { VertexAttrib4d(ctx, index, x, y, z, w); }
void VertexAttrib4dvARB(Context& ctx, GLuint index, const GLdouble * v) { VertexAttrib4dv(ctx, index, v); }
void VertexAttrib4bvARB(Context& ctx, GLuint index, const GLbyte * v) { VertexAttrib4bv(ctx, index, v); }
void VertexAttrib4NbvARB(Context& ctx, GLuint index, const GLbyte * v) { VertexAttrib4Nbv(ctx, index, v); }
void VertexAttrib4ubvARB(Context& ctx, GLuint index, const GLubyte * v) { VertexAttrib4ubv(ctx, index, v); }
void VertexAttrib4NubvARB(Context& ctx, GLuint index, const GLubyte * v) { VertexAttrib4Nubv(ctx, index, v); }
void VertexAttrib4ivARB(Context& ctx, GLuint index, const GLint * v) { VertexAttrib4iv(ctx, index, v); }
void VertexAttrib4NivARB(Context& ctx, GLuint index, const GLint * v) { VertexAttrib4Niv(ctx, index, v); }
void VertexAttrib4uivARB(Context& ctx, GLuint index, const GLuint * v) { VertexAttrib4uiv(ctx, index, v); }
void VertexAttrib4NuivARB(Context& ctx, GLuint index, const GLuint * v) { VertexAttrib4Nuiv(ctx, index, v); }
void VertexAttrib4usvARB(Context& ctx, GLuint index, const GLushort * v) { VertexAttrib4usv(ctx, index, v); }
void VertexAttrib4NusvARB(Context& ctx, GLuint index, const GLushort * v) { VertexAttrib4Nusv(ctx, index, v); }
void VertexAttrib4NsvARB(Context& ctx, GLuint index, const GLshort * v) { VertexAttrib4Nsv(ctx, index, v); }
void VertexAttrib4NubARB(Context& ctx, GLuint index, GLubyte x, GLubyte y, GLubyte z, GLubyte w) { VertexAttrib4Nub(ctx, index, x, y, z, w); }

}  // namespace pineda::gl
