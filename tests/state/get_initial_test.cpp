// Every queryable GL 1.1 state has its initial value from the spec's state tables.
#include <cmath>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class InitialStateTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {40, 24, 24, 8}; }
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
};

using Floats = std::vector<GLfloat>;
using Ints = std::vector<GLint>;

TEST_F(InitialStateTest, CurrentValues) {
  EXPECT_EQ(get_floats(GL_CURRENT_COLOR, 4), (Floats{1, 1, 1, 1}));
  EXPECT_EQ(get_floats(GL_CURRENT_TEXTURE_COORDS, 4), (Floats{0, 0, 0, 1}));
  EXPECT_EQ(get_floats(GL_CURRENT_NORMAL, 3), (Floats{0, 0, 1}));
  EXPECT_EQ(get_bool(GL_EDGE_FLAG), GL_TRUE);
}

TEST_F(InitialStateTest, Transformation) {
  EXPECT_EQ(get_int(GL_MATRIX_MODE), GL_MODELVIEW);
  const Floats identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_EQ(get_floats(GL_MODELVIEW_MATRIX, 16), identity);
  EXPECT_EQ(get_floats(GL_PROJECTION_MATRIX, 16), identity);
  EXPECT_EQ(get_floats(GL_TEXTURE_MATRIX, 16), identity);
  EXPECT_EQ(get_int(GL_MODELVIEW_STACK_DEPTH), 1);
  EXPECT_EQ(get_int(GL_PROJECTION_STACK_DEPTH), 1);
  EXPECT_EQ(get_int(GL_TEXTURE_STACK_DEPTH), 1);
  EXPECT_EQ(get_ints(GL_VIEWPORT, 4), (Ints{0, 0, 40, 24}));
  EXPECT_EQ(get_floats(GL_DEPTH_RANGE, 2), (Floats{0, 1}));
  EXPECT_EQ(glIsEnabled(GL_NORMALIZE), GL_FALSE);
}

TEST_F(InitialStateTest, Lighting) {
  EXPECT_EQ(get_int(GL_SHADE_MODEL), GL_SMOOTH);
  EXPECT_EQ(glIsEnabled(GL_LIGHTING), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_MATERIAL), GL_FALSE);
  EXPECT_EQ(get_int(GL_COLOR_MATERIAL_FACE), GL_FRONT_AND_BACK);
  EXPECT_EQ(get_int(GL_COLOR_MATERIAL_PARAMETER), GL_AMBIENT_AND_DIFFUSE);
  EXPECT_EQ(get_floats(GL_LIGHT_MODEL_AMBIENT, 4), (Floats{0.2f, 0.2f, 0.2f, 1.0f}));
  EXPECT_EQ(get_bool(GL_LIGHT_MODEL_LOCAL_VIEWER), GL_FALSE);
  EXPECT_EQ(get_bool(GL_LIGHT_MODEL_TWO_SIDE), GL_FALSE);
  const GLint max_lights = get_int(GL_MAX_LIGHTS);
  EXPECT_GE(max_lights, 8);
  for (GLint i = 0; i < max_lights; ++i) EXPECT_EQ(glIsEnabled(GL_LIGHT0 + i), GL_FALSE) << i;
}

TEST_F(InitialStateTest, Rasterization) {
  EXPECT_EQ(get_float(GL_POINT_SIZE), 1.f);
  EXPECT_EQ(glIsEnabled(GL_POINT_SMOOTH), GL_FALSE);
  EXPECT_EQ(get_float(GL_LINE_WIDTH), 1.f);
  EXPECT_EQ(glIsEnabled(GL_LINE_SMOOTH), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_LINE_STIPPLE), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_CULL_FACE), GL_FALSE);
  EXPECT_EQ(get_int(GL_CULL_FACE_MODE), GL_BACK);
  EXPECT_EQ(get_int(GL_FRONT_FACE), GL_CCW);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_SMOOTH), GL_FALSE);
  EXPECT_EQ(get_ints(GL_POLYGON_MODE, 2), (Ints{GL_FILL, GL_FILL}));
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_FACTOR), 0.f);
  EXPECT_EQ(get_float(GL_POLYGON_OFFSET_UNITS), 0.f);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_OFFSET_FILL), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_OFFSET_LINE), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_OFFSET_POINT), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_STIPPLE), GL_FALSE);
}

TEST_F(InitialStateTest, Texturing) {
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_1D), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_2D), GL_FALSE);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_1D), 0);
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), 0);
  for (GLenum c : {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q})
    EXPECT_EQ(glIsEnabled(c), GL_FALSE);
}

TEST_F(InitialStateTest, PixelOperations) {
  EXPECT_EQ(glIsEnabled(GL_SCISSOR_TEST), GL_FALSE);
  EXPECT_EQ(get_ints(GL_SCISSOR_BOX, 4), (Ints{0, 0, 40, 24}));
  EXPECT_EQ(glIsEnabled(GL_ALPHA_TEST), GL_FALSE);
  EXPECT_EQ(get_int(GL_ALPHA_TEST_FUNC), GL_ALWAYS);
  EXPECT_EQ(get_float(GL_ALPHA_TEST_REF), 0.f);
  EXPECT_EQ(glIsEnabled(GL_STENCIL_TEST), GL_FALSE);
  EXPECT_EQ(get_int(GL_STENCIL_FUNC), GL_ALWAYS);
  EXPECT_EQ(get_int(GL_STENCIL_REF), 0);
  EXPECT_EQ(get_int(GL_STENCIL_VALUE_MASK) & 0xff, 0xff);  // all ones in at least the stencil bits
  EXPECT_EQ(get_int(GL_STENCIL_FAIL), GL_KEEP);
  EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_FAIL), GL_KEEP);
  EXPECT_EQ(get_int(GL_STENCIL_PASS_DEPTH_PASS), GL_KEEP);
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_LESS);
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
  EXPECT_EQ(get_int(GL_BLEND_SRC), GL_ONE);
  EXPECT_EQ(get_int(GL_BLEND_DST), GL_ZERO);
  EXPECT_EQ(glIsEnabled(GL_DITHER), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_LOGIC_OP), GL_FALSE);
  EXPECT_EQ(get_int(GL_LOGIC_OP_MODE), GL_COPY);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION), GL_FUNC_ADD);
  EXPECT_EQ(get_floats(GL_BLEND_COLOR, 4), (Floats{0, 0, 0, 0}));
}

TEST_F(InitialStateTest, FramebufferControl) {
  EXPECT_EQ(get_bools(GL_COLOR_WRITEMASK, 4), (std::vector<GLboolean>{1, 1, 1, 1}));
  EXPECT_EQ(get_bool(GL_DEPTH_WRITEMASK), GL_TRUE);
  EXPECT_EQ(get_int(GL_STENCIL_WRITEMASK) & 0xff, 0xff);
  EXPECT_EQ(get_floats(GL_COLOR_CLEAR_VALUE, 4), (Floats{0, 0, 0, 0}));
  EXPECT_EQ(get_float(GL_DEPTH_CLEAR_VALUE), 1.f);
  EXPECT_EQ(get_int(GL_STENCIL_CLEAR_VALUE), 0);
  const GLboolean double_buffered = get_bool(GL_DOUBLEBUFFER);
  EXPECT_EQ(get_int(GL_DRAW_BUFFER), double_buffered ? GL_BACK : GL_FRONT);
  EXPECT_EQ(get_int(GL_READ_BUFFER), double_buffered ? GL_BACK : GL_FRONT);
}

TEST_F(InitialStateTest, PixelStore) {
  for (GLenum p : {GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_UNPACK_ROW_LENGTH,
                   GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS})
    EXPECT_EQ(get_int(p), 0) << std::hex << p;
  EXPECT_EQ(get_int(GL_PACK_ALIGNMENT), 4);
  EXPECT_EQ(get_int(GL_UNPACK_ALIGNMENT), 4);
  for (GLenum p : {GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST})
    EXPECT_EQ(get_bool(p), GL_FALSE) << std::hex << p;
}

TEST_F(InitialStateTest, Hints) {
  for (GLenum h : {GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT, GL_LINE_SMOOTH_HINT,
                   GL_POLYGON_SMOOTH_HINT, GL_FOG_HINT})
    EXPECT_EQ(get_int(h), GL_DONT_CARE) << std::hex << h;
}

TEST_F(InitialStateTest, ClientArrays) {
  for (GLenum a : {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_INDEX_ARRAY, GL_TEXTURE_COORD_ARRAY,
                   GL_EDGE_FLAG_ARRAY})
    EXPECT_EQ(glIsEnabled(a), GL_FALSE) << std::hex << a;
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_SIZE), 4);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(get_int(GL_VERTEX_ARRAY_STRIDE), 0);
  EXPECT_EQ(get_int(GL_NORMAL_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(get_int(GL_NORMAL_ARRAY_STRIDE), 0);
  EXPECT_EQ(get_int(GL_COLOR_ARRAY_SIZE), 4);
  EXPECT_EQ(get_int(GL_COLOR_ARRAY_TYPE), GL_FLOAT);
  EXPECT_EQ(get_int(GL_TEXTURE_COORD_ARRAY_SIZE), 4);
  EXPECT_EQ(get_int(GL_TEXTURE_COORD_ARRAY_TYPE), GL_FLOAT);
  for (GLenum p : {GL_VERTEX_ARRAY_POINTER, GL_NORMAL_ARRAY_POINTER, GL_COLOR_ARRAY_POINTER,
                   GL_TEXTURE_COORD_ARRAY_POINTER}) {
    void* ptr = &ptr;
    glGetPointerv(p, &ptr);
    EXPECT_EQ(ptr, nullptr) << std::hex << p;
  }
}

TEST_F(InitialStateTest, ImplementationLimits) {
  EXPECT_GE(get_int(GL_MAX_MODELVIEW_STACK_DEPTH), 32);
  EXPECT_GE(get_int(GL_MAX_PROJECTION_STACK_DEPTH), 2);
  EXPECT_GE(get_int(GL_MAX_TEXTURE_STACK_DEPTH), 2);
  EXPECT_GE(get_int(GL_MAX_TEXTURE_SIZE), 64);
  EXPECT_GE(get_int(GL_SUBPIXEL_BITS), 4);
  const Ints dims = get_ints(GL_MAX_VIEWPORT_DIMS, 2);
  EXPECT_GE(dims[0], 40);
  EXPECT_GE(dims[1], 24);
  const Floats points = get_floats(GL_POINT_SIZE_RANGE, 2);
  EXPECT_LE(points[0], 1.f);
  EXPECT_GE(points[1], 1.f);
  EXPECT_GE(get_int(GL_MAX_ATTRIB_STACK_DEPTH), 16);
  EXPECT_GE(get_int(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH), 16);
  EXPECT_GE(get_int(GL_MAX_NAME_STACK_DEPTH), 64);
  EXPECT_GE(get_int(GL_MAX_LIST_NESTING), 64);
  EXPECT_GE(get_int(GL_MAX_EVAL_ORDER), 8);
  EXPECT_GE(get_int(GL_MAX_PIXEL_MAP_TABLE), 32);
  EXPECT_GT(get_float(GL_POINT_SIZE_GRANULARITY), 0.f);
  EXPECT_GT(get_float(GL_LINE_WIDTH_GRANULARITY), 0.f);
  const Floats lines = get_floats(GL_LINE_WIDTH_RANGE, 2);
  EXPECT_LE(lines[0], 1.f);
  EXPECT_GE(lines[1], 1.f);
}

TEST_F(InitialStateTest, FramebufferBits) {
  EXPECT_EQ(get_int(GL_RED_BITS), 8);
  EXPECT_EQ(get_int(GL_GREEN_BITS), 8);
  EXPECT_EQ(get_int(GL_BLUE_BITS), 8);
  EXPECT_EQ(get_int(GL_ALPHA_BITS), 8);
  EXPECT_EQ(get_int(GL_DEPTH_BITS), 24);
  EXPECT_EQ(get_int(GL_STENCIL_BITS), 8);
  EXPECT_EQ(get_bool(GL_RGBA_MODE), GL_TRUE);
  EXPECT_EQ(get_bool(GL_INDEX_MODE), GL_FALSE);
  EXPECT_EQ(get_bool(GL_STEREO), GL_FALSE);
  for (GLenum p : {GL_ACCUM_RED_BITS, GL_ACCUM_GREEN_BITS, GL_ACCUM_BLUE_BITS, GL_ACCUM_ALPHA_BITS})
    EXPECT_EQ(get_int(p), 16) << std::hex << p;
  for (GLenum p : {GL_INDEX_BITS, GL_AUX_BUFFERS}) EXPECT_EQ(get_int(p), 0) << std::hex << p;
}

}  // namespace
}  // namespace pineda::test
