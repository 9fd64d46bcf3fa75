// GL 1.3 multisample state (ARB_multisample) on single-sampled framebuffers: the values and
// enables are kept and reported; with SAMPLE_BUFFERS 0 they change no fragment.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class MultisampleStateTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
};

constexpr GLenum kEnables[] = {GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE,
                               GL_SAMPLE_COVERAGE};

TEST_F(MultisampleStateTest, InitialValues) {
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_ALPHA_TO_ONE), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_COVERAGE), GL_FALSE);
  EXPECT_EQ(get_float(GL_SAMPLE_COVERAGE_VALUE), 1.f);
  EXPECT_EQ(get_bool(GL_SAMPLE_COVERAGE_INVERT), GL_FALSE);
  EXPECT_EQ(get_int(GL_SAMPLE_BUFFERS), 0);
  EXPECT_EQ(get_int(GL_SAMPLES), 0);
  EXPECT_EQ(get_bool(GL_MULTISAMPLE), GL_TRUE);
}

TEST_F(MultisampleStateTest, SampleCoverageClampsTheValue) {
  glSampleCoverage(0.25f, GL_TRUE);
  EXPECT_EQ(get_float(GL_SAMPLE_COVERAGE_VALUE), 0.25f);
  EXPECT_EQ(get_bool(GL_SAMPLE_COVERAGE_INVERT), GL_TRUE);
  glSampleCoverage(2.f, GL_FALSE);
  EXPECT_EQ(get_float(GL_SAMPLE_COVERAGE_VALUE), 1.f);
  EXPECT_EQ(get_bool(GL_SAMPLE_COVERAGE_INVERT), GL_FALSE);
  glSampleCoverageARB(-1.f, GL_TRUE);
  EXPECT_EQ(get_float(GL_SAMPLE_COVERAGE_VALUE), 0.f);
  EXPECT_EQ(get_bool(GL_SAMPLE_COVERAGE_INVERT), GL_TRUE);
}

TEST_F(MultisampleStateTest, EnablesToggle) {
  for (GLenum cap : kEnables) {
    glEnable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_TRUE) << cap;
    glDisable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE) << cap;
    EXPECT_EQ(get_bool(cap), GL_FALSE) << cap;
  }
}

TEST_F(MultisampleStateTest, MultisampleBitSavesEverything) {
  glSampleCoverage(0.5f, GL_TRUE);
  glEnable(GL_SAMPLE_COVERAGE);
  glPushAttrib(GL_MULTISAMPLE_BIT);
  glSampleCoverage(0.75f, GL_FALSE);
  for (GLenum cap : kEnables) glDisable(cap);
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  glPopAttrib();
  EXPECT_EQ(get_float(GL_SAMPLE_COVERAGE_VALUE), 0.5f);
  EXPECT_EQ(get_bool(GL_SAMPLE_COVERAGE_INVERT), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_COVERAGE), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_ALPHA_TO_ONE), GL_FALSE);
}

TEST_F(MultisampleStateTest, EnableBitSavesOnlyTheEnables) {
  glPushAttrib(GL_ENABLE_BIT);
  glSampleCoverage(0.5f, GL_TRUE);
  glDisable(GL_MULTISAMPLE);
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE), GL_FALSE);
  EXPECT_EQ(get_float(GL_SAMPLE_COVERAGE_VALUE), 0.5f);  // not in the enable group
  EXPECT_EQ(get_bool(GL_SAMPLE_COVERAGE_INVERT), GL_TRUE);
}

TEST_F(MultisampleStateTest, NoEffectWithoutSampleBuffers) {
  // GL 1.5 3.2.1: with SAMPLE_BUFFERS 0 multisample rasterization is off, so neither the
  // coverage value 0 nor alpha-to-one/coverage touches the fragments.
  pixel_projection();
  glEnable(GL_SAMPLE_COVERAGE);
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  glSampleCoverage(0.f, GL_FALSE);
  clear_to(0, 0, 0, 0);
  glColor4f(1.f, 0.f, 1.f, 0.f);
  glRectf(0, 0, 10, 10);
  EXPECT_EQ(count_pixels({255, 0, 255, 0}), 100);
}

TEST_F(MultisampleStateTest, BadCapabilityStillRejected) {
  glEnable(GL_SAMPLE_COVERAGE_VALUE);  // a value, not a capability
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

}  // namespace
}  // namespace pineda::test
