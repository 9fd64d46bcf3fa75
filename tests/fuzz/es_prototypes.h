// The OpenGL ES entry points that desktop GL's headers do not declare (GLES/gl.h cannot be
// included beside GL/gl.h): ES 1.1's fixed-point calls without the OES suffix and its
// single-precision ones, OES_draw_texture, OES_point_size_array, the OES blend and buffer
// names, and the KHR/EXT names of debug output and robustness.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

extern "C" {
void glAlphaFuncx(GLenum func, GLfixed ref);
void glBindVertexArrayOES(GLuint array);
void glBlendEquationOES(GLenum mode);
void glBlendEquationSeparateOES(GLenum modeRGB, GLenum modeAlpha);
void glBlendFuncSeparateOES(GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha);
void glClearColorx(GLfixed red, GLfixed green, GLfixed blue, GLfixed alpha);
void glClearDepthx(GLfixed depth);
void glClipPlanef(GLenum p, const GLfloat *eqn);
void glClipPlanex(GLenum plane, const GLfixed *equation);
void glColor4x(GLfixed red, GLfixed green, GLfixed blue, GLfixed alpha);
void glDebugMessageCallbackKHR(GLDEBUGPROC callback, const void *userParam);
void glDebugMessageControlKHR(GLenum source, GLenum type, GLenum severity, GLsizei count, const GLuint *ids, GLboolean enabled);
void glDebugMessageInsertKHR(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length, const GLchar *buf);
void glDeleteVertexArraysOES(GLsizei n, const GLuint *arrays);
void glDepthRangex(GLfixed n, GLfixed f);
void glDiscardFramebufferEXT(GLenum target, GLsizei numAttachments, const GLenum *attachments);
void glDrawBuffersEXT(GLsizei n, const GLenum *bufs);
void glDrawTexfOES(GLfloat x, GLfloat y, GLfloat z, GLfloat width, GLfloat height);
void glDrawTexfvOES(const GLfloat *coords);
void glDrawTexiOES(GLint x, GLint y, GLint z, GLint width, GLint height);
void glDrawTexivOES(const GLint *coords);
void glDrawTexsOES(GLshort x, GLshort y, GLshort z, GLshort width, GLshort height);
void glDrawTexsvOES(const GLshort *coords);
void glDrawTexxOES(GLfixed x, GLfixed y, GLfixed z, GLfixed width, GLfixed height);
void glDrawTexxvOES(const GLfixed *coords);
void glFogx(GLenum pname, GLfixed param);
void glFogxv(GLenum pname, const GLfixed *param);
void glFrustumf(GLfloat l, GLfloat r, GLfloat b, GLfloat t, GLfloat n, GLfloat f);
void glFrustumx(GLfixed l, GLfixed r, GLfixed b, GLfixed t, GLfixed n, GLfixed f);
void glGenVertexArraysOES(GLsizei n, GLuint *arrays);
void glGetBufferPointervOES(GLenum target, GLenum pname, void **params);
void glGetClipPlanef(GLenum plane, GLfloat *equation);
void glGetClipPlanex(GLenum plane, GLfixed *equation);
GLuint glGetDebugMessageLogKHR(GLuint count, GLsizei bufSize, GLenum *sources, GLenum *types, GLuint *ids, GLenum *severities, GLsizei *lengths, GLchar *messageLog);
void glGetFixedv(GLenum pname, GLfixed *params);
GLenum glGetGraphicsResetStatusEXT(void);
GLenum glGetGraphicsResetStatusKHR(void);
void glGetLightxv(GLenum light, GLenum pname, GLfixed *params);
void glGetLightxvOES(GLenum light, GLenum pname, GLfixed *params);
void glGetMaterialxv(GLenum face, GLenum pname, GLfixed *params);
void glGetMaterialxvOES(GLenum face, GLenum pname, GLfixed *params);
void glGetObjectLabelKHR(GLenum identifier, GLuint name, GLsizei bufSize, GLsizei *length, GLchar *label);
void glGetObjectPtrLabelKHR(const void *ptr, GLsizei bufSize, GLsizei *length, GLchar *label);
void glGetPointervKHR(GLenum pname, void **params);
void glGetTexEnvxv(GLenum target, GLenum pname, GLfixed *params);
void glGetTexParameterxv(GLenum target, GLenum pname, GLfixed *params);
void glGetnUniformfvEXT(GLuint program, GLint location, GLsizei bufSize, GLfloat *params);
void glGetnUniformfvKHR(GLuint program, GLint location, GLsizei bufSize, GLfloat *params);
void glGetnUniformivEXT(GLuint program, GLint location, GLsizei bufSize, GLint *params);
void glGetnUniformivKHR(GLuint program, GLint location, GLsizei bufSize, GLint *params);
void glGetnUniformuivKHR(GLuint program, GLint location, GLsizei bufSize, GLuint *params);
GLboolean glIsVertexArrayOES(GLuint array);
void glLightModelx(GLenum pname, GLfixed param);
void glLightModelxv(GLenum pname, const GLfixed *param);
void glLightx(GLenum light, GLenum pname, GLfixed param);
void glLightxv(GLenum light, GLenum pname, const GLfixed *params);
void glLineWidthx(GLfixed width);
void glLoadMatrixx(const GLfixed *m);
void* glMapBufferOES(GLenum target, GLenum access);
void glMaterialx(GLenum face, GLenum pname, GLfixed param);
void glMaterialxv(GLenum face, GLenum pname, const GLfixed *param);
void glMultMatrixx(const GLfixed *m);
void glMultiTexCoord4x(GLenum texture, GLfixed s, GLfixed t, GLfixed r, GLfixed q);
void glNormal3x(GLfixed nx, GLfixed ny, GLfixed nz);
void glObjectLabelKHR(GLenum identifier, GLuint name, GLsizei length, const GLchar *label);
void glObjectPtrLabelKHR(const void *ptr, GLsizei length, const GLchar *label);
void glOrthof(GLfloat l, GLfloat r, GLfloat b, GLfloat t, GLfloat n, GLfloat f);
void glOrthox(GLfixed l, GLfixed r, GLfixed b, GLfixed t, GLfixed n, GLfixed f);
void glPointParameterx(GLenum pname, GLfixed param);
void glPointParameterxOES(GLenum pname, GLfixed param);
void glPointParameterxv(GLenum pname, const GLfixed *params);
void glPointSizePointerOES(GLenum type, GLsizei stride, const void *pointer);
void glPointSizex(GLfixed size);
void glPolygonOffsetx(GLfixed factor, GLfixed units);
void glPopDebugGroupKHR(void);
void glPushDebugGroupKHR(GLenum source, GLuint id, GLsizei length, const GLchar *message);
void glReadnPixelsEXT(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, GLsizei bufSize, void *data);
void glReadnPixelsKHR(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, GLsizei bufSize, void *data);
void glRotatex(GLfixed angle, GLfixed x, GLfixed y, GLfixed z);
void glSampleCoveragex(GLfixed value, GLboolean invert);
void glSampleCoveragexOES(GLfixed value, GLboolean invert);
void glScalex(GLfixed x, GLfixed y, GLfixed z);
void glTexEnvx(GLenum target, GLenum pname, GLfixed param);
void glTexEnvxv(GLenum target, GLenum pname, const GLfixed *params);
void glTexParameterx(GLenum target, GLenum pname, GLfixed param);
void glTexParameterxv(GLenum target, GLenum pname, const GLfixed *params);
void glTranslatex(GLfixed x, GLfixed y, GLfixed z);
GLboolean glUnmapBufferOES(GLenum target);
}
