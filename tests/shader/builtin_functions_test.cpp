// Every built-in function over 16 lanes, with GLSL's edge cases, against exact values.
#include <cmath>
#include <limits>

#include "tests/shader/shader_test_util.h"

namespace pineda::shader::test {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Lane l of component c of varying a: a small table of interesting values.
float interesting(int l, int c) {
  static const float v[16] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, -0.5f, 2.5f, -2.5f,
                              3.0f, -7.25f, 100.0f, 1e-3f, 0.75f, -3.5f, 10.0f, 1.5f};
  return v[(l + 3 * c) & 15];
}
float second(int l, int c) {
  static const float v[16] = {1.0f, 2.0f, -1.0f, 0.5f, 3.0f, -2.0f, 0.25f, 4.0f,
                              -3.0f, 1.5f, 2.0f, -0.5f, 8.0f, 0.75f, -4.0f, 5.0f};
  return v[(l + 5 * c) & 15];
}

template <class F>
void expect_lanes(const ExprResult& r, int component, F expected, const char* what) {
  for (int l = 0; l < kLanes; ++l) {
    const float e = expected(l);
    if (std::isnan(e)) EXPECT_TRUE(std::isnan(r.c[component][l])) << what << " lane " << l;
    else EXPECT_EQ(r.c[component][l], e) << what << " lane " << l;
  }
}

#define UNARY_TEST(NAME, GLSL, EXPR)                                                    \
  TEST(BuiltinFunctions, NAME) {                                                        \
    ExprResult r = run_fragment("gl_FragColor = " GLSL "(a);", interesting);            \
    for (int c = 0; c < 4; ++c)                                                         \
      expect_lanes(r, c, [&](int l) { float x = interesting(l, c); return (EXPR); }, GLSL); \
  }

UNARY_TEST(Abs, "abs", std::fabs(x))
UNARY_TEST(Sign, "sign", x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f))
UNARY_TEST(Floor, "floor", std::floor(x))
UNARY_TEST(Ceil, "ceil", std::ceil(x))
UNARY_TEST(Fract, "fract", x - std::floor(x))
// sin and cos are correctly rounded (shader/lane_sin_cos.inc): the double result rounded once.
UNARY_TEST(Sin, "sin", static_cast<float>(std::sin(static_cast<double>(x))))
UNARY_TEST(Cos, "cos", static_cast<float>(std::cos(static_cast<double>(x))))
UNARY_TEST(Tan, "tan", std::tan(x))
UNARY_TEST(Atan, "atan", std::atan(x))
// exp and exp2 are correctly rounded here (shader/lane_pow.inc: 2^t in double, rounded once).
UNARY_TEST(Exp, "exp", static_cast<float>(std::exp(static_cast<double>(x))))
UNARY_TEST(Exp2, "exp2", static_cast<float>(std::exp2(static_cast<double>(x))))
UNARY_TEST(Negate, "-", -x)

// exp and exp2 at the ends of float's range, at infinities and NaN (glslang folds constants).
TEST(BuiltinFunctions, ExpAndExp2EdgesAndConstants) {
  const auto edges = [](int l, int) {
    static const float v[16] = {kInf, -kInf, std::numeric_limits<float>::quiet_NaN(), 128.0f, -150.0f, 127.5f, -126.0f,
                                0.5f, 1.0f, 20.0f, -20.0f, 88.7f, -87.5f, 1e-8f, -1e-8f, -126.5f};
    return v[l];
  };
  ExprResult r = run_fragment("gl_FragColor = vec4(exp2(a.x), exp(a.x), exp2(-a.x), exp(1.0));", edges);
  // Rounded once to float; below FLT_MIN, zero (denormals are flushed while shaders run).
  const auto rounded = [](double v) {
    const float f = static_cast<float>(v);
    return std::fabs(f) < std::numeric_limits<float>::min() ? 0.0f : f;
  };
  expect_lanes(r, 0, [&](int l) { return rounded(std::exp2(static_cast<double>(edges(l, 0)))); }, "exp2");
  expect_lanes(r, 1, [&](int l) { return rounded(std::exp(static_cast<double>(edges(l, 0)))); }, "exp");
  EXPECT_EQ(r.c[0][0], kInf);
  EXPECT_EQ(r.c[0][1], 0.0f);
  EXPECT_TRUE(std::isnan(r.c[0][2]));
  EXPECT_EQ(r.c[0][6], std::numeric_limits<float>::min());  // 2^-126
  EXPECT_EQ(r.c[0][15], 0.0f);                              // 2^-126.5
  expect_lanes(r, 2, [&](int l) { return rounded(std::exp2(-static_cast<double>(edges(l, 0)))); }, "exp2(-x)");
  expect_lanes(r, 3, [](int) { return static_cast<float>(std::exp(1.0)); }, "exp const");
}

// Arguments over many quadrants, and beyond 2^17 (reduced by C's sin and cos in double), and a
// constant folded at link time against the same value computed per lane.
TEST(BuiltinFunctions, SinCosLargeArgumentsAndConstants) {
  ExprResult r = run_fragment("gl_FragColor = vec4(sin(a.x * 1000.0), cos(a.x * 1000.0), sin(a.x * 1e6), cos(2.5));",
                              interesting);
  auto rounded = [](float x, bool cosine) {
    return static_cast<float>(cosine ? std::cos(static_cast<double>(x)) : std::sin(static_cast<double>(x)));
  };
  expect_lanes(r, 0, [&](int l) { return rounded(interesting(l, 0) * 1000.0f, false); }, "sin(1000 x)");
  expect_lanes(r, 1, [&](int l) { return rounded(interesting(l, 0) * 1000.0f, true); }, "cos(1000 x)");
  expect_lanes(r, 2, [&](int l) { return rounded(interesting(l, 0) * 1e6f, false); }, "sin(1e6 x)");
  ExprResult lanes = run_fragment("gl_FragColor = vec4(cos(a.x));", interesting);
  EXPECT_EQ(r.c[3][0], lanes.c[0][6]);  // interesting(6, 0) is 2.5
}

TEST(BuiltinFunctions, AsinAcosOutsideDomainAreNan) {
  ExprResult r = run_fragment("gl_FragColor = vec4(asin(a.x), acos(a.x), asin(0.5), acos(-1.0));", interesting);
  expect_lanes(r, 0, [](int l) { return std::asin(interesting(l, 0)); }, "asin");
  expect_lanes(r, 1, [](int l) { return std::acos(interesting(l, 0)); }, "acos");
  expect_lanes(r, 2, [](int) { return std::asin(0.5f); }, "asin const");
  expect_lanes(r, 3, [](int) { return std::acos(-1.0f); }, "acos const");
}

TEST(BuiltinFunctions, LogSqrtInverseSqrtEdges) {
  ExprResult r = run_fragment("gl_FragColor = vec4(log(a.x), log2(a.x), sqrt(a.x), inversesqrt(a.x));", interesting);
  expect_lanes(r, 0, [](int l) { return std::log(interesting(l, 0)); }, "log");
  expect_lanes(r, 1, [](int l) { return std::log2(interesting(l, 0)); }, "log2");
  expect_lanes(r, 2, [](int l) { return std::sqrt(interesting(l, 0)); }, "sqrt");
  expect_lanes(r, 3, [](int l) { return 1.0f / std::sqrt(interesting(l, 0)); }, "inversesqrt");
  EXPECT_EQ(r.c[0][0], -kInf);   // log(0)
  EXPECT_EQ(r.c[3][0], kInf);    // inversesqrt(0)
  EXPECT_TRUE(std::isnan(r.c[2][3]));  // sqrt(-1)
}

TEST(BuiltinFunctions, RadiansDegrees) {
  ExprResult r = run_fragment("gl_FragColor = vec4(radians(a.x), degrees(a.x), radians(180.0), degrees(3.14159265));", interesting);
  expect_lanes(r, 0, [](int l) { return interesting(l, 0) * static_cast<float>(M_PI / 180.0); }, "radians");
  expect_lanes(r, 1, [](int l) { return interesting(l, 0) * static_cast<float>(180.0 / M_PI); }, "degrees");
  EXPECT_EQ(r.c[2][0], 180.0f * static_cast<float>(M_PI / 180.0));
  EXPECT_EQ(r.c[3][0], 3.14159265f * static_cast<float>(180.0 / M_PI));
}

TEST(BuiltinFunctions, PowAndAtan2) {
  ExprResult r = run_fragment("gl_FragColor = vec4(pow(abs(a.x), b.x), atan(a.x, b.x), atan(0.0, -1.0), atan(-1.0, 0.0));",
                              interesting, second);
  expect_lanes(r, 0, [](int l) { return std::pow(std::fabs(interesting(l, 0)), second(l, 0)); }, "pow");
  expect_lanes(r, 1, [](int l) { return std::atan2(interesting(l, 0), second(l, 0)); }, "atan2");
  EXPECT_EQ(r.c[2][0], std::atan2(0.0f, -1.0f));
  EXPECT_EQ(r.c[3][0], std::atan2(-1.0f, 0.0f));
  // pow(0, 0) is 1 here; pow(0, negative) is +inf (GLSL leaves both undefined).
  ExprResult z = run_fragment("gl_FragColor = vec4(pow(0.0, a.z * 0.0), pow(a.z * 0.0, -1.0), 0.0, 0.0);", interesting);
  EXPECT_EQ(z.c[0][5], 1.0f);
}

// Whole exponents up to 256 multiply (shader/lane_pow.inc): the same exponent in every lane, a
// negative one, and odd powers of negative bases, against the correctly rounded power.
TEST(BuiltinFunctions, PowWholeExponents) {
  ExprResult r = run_fragment("gl_FragColor = vec4(pow(abs(a.x), 32.0), pow(abs(a.x), -3.0), pow(a.x, 3.0), "
                              "pow(abs(a.x) * 0.01 + 1.0, 255.0));",
                              interesting);
  auto rounded = [](double x, double y) {
    const float p = static_cast<float>(std::pow(x, y));
    return std::fabs(p) < std::numeric_limits<float>::min() ? 0.0f * p : p;
  };
  expect_lanes(r, 0, [&](int l) { return rounded(std::fabs(interesting(l, 0)), 32.0); }, "pow 32");
  expect_lanes(r, 1, [&](int l) { return rounded(std::fabs(interesting(l, 0)), -3.0); }, "pow -3");
  expect_lanes(r, 2, [&](int l) { return rounded(interesting(l, 0), 3.0); }, "pow 3");
  expect_lanes(r, 3, [&](int l) { return rounded(std::fabs(interesting(l, 0)) * 0.01f + 1.0f, 255.0); }, "pow 255");
  EXPECT_EQ(r.c[0][10], kInf);     // 100^32 overflows
  EXPECT_EQ(r.c[1][0], kInf);      // 0^-3
  EXPECT_EQ(r.c[2][1], -0.0f);     // (-0)^3
  EXPECT_TRUE(std::signbit(r.c[2][1]));
  EXPECT_EQ(r.c[2][9], -381.078125f);  // (-7.25)^3, exact
}

TEST(BuiltinFunctions, ModMinMaxClamp) {
  ExprResult r = run_fragment("gl_FragColor = vec4(mod(a.x, b.x), min(a.x, b.x), max(a.x, b.x), clamp(a.x, -1.0, 2.0));",
                              interesting, second);
  expect_lanes(r, 0, [](int l) { float x = interesting(l, 0), y = second(l, 0); return x - y * std::floor(x / y); }, "mod");
  expect_lanes(r, 1, [](int l) { return std::fmin(interesting(l, 0), second(l, 0)); }, "min");
  expect_lanes(r, 2, [](int l) { return std::fmax(interesting(l, 0), second(l, 0)); }, "max");
  expect_lanes(r, 3, [](int l) { return std::fmin(std::fmax(interesting(l, 0), -1.0f), 2.0f); }, "clamp");
  // mod of a negative number is positive for a positive divisor: mod(-7.25, 1.5) = 0.25.
  ExprResult m = run_fragment("gl_FragColor = vec4(mod(-7.25, a.w * 0.0 + 1.5), mod(a.xy, 2.0), 0.0);", interesting);
  EXPECT_EQ(m.c[0][0], 0.25f);
  expect_lanes(m, 1, [](int l) { float x = interesting(l, 0); return x - 2.0f * std::floor(x / 2.0f); }, "mod vec,float");
}

TEST(BuiltinFunctions, MixStepSmoothstep) {
  ExprResult r = run_fragment(
      "gl_FragColor = vec4(mix(a.x, b.x, 0.25), step(0.5, a.x), smoothstep(-1.0, 2.0, a.x), smoothstep(1.0, 1.0, a.x));",
      interesting, second);
  expect_lanes(r, 0, [](int l) { return interesting(l, 0) * (1.0f - 0.25f) + second(l, 0) * 0.25f; }, "mix");
  expect_lanes(r, 1, [](int l) { return interesting(l, 0) < 0.5f ? 0.0f : 1.0f; }, "step");
  expect_lanes(r, 2, [](int l) {
    float t = std::fmin(std::fmax((interesting(l, 0) + 1.0f) / 3.0f, 0.0f), 1.0f);
    return t * t * (3.0f - 2.0f * t);
  }, "smoothstep");
  // Equal edges: 0 below, 1 above, 0 at the edge (no NaN comes out).
  expect_lanes(r, 3, [](int l) { float x = interesting(l, 0); return x > 1.0f ? 1.0f : 0.0f; }, "smoothstep equal edges");
  ExprResult v = run_fragment("gl_FragColor = mix(a, b, vec4(0.0, 1.0, 0.5, 2.0));", interesting, second);
  expect_lanes(v, 1, [](int l) { return interesting(l, 1) * 0.0f + second(l, 1) * 1.0f; }, "mix vec a=1");
  expect_lanes(v, 3, [](int l) { return interesting(l, 3) * -1.0f + second(l, 3) * 2.0f; }, "mix vec a=2");
}

TEST(BuiltinFunctions, GeometricFunctions) {
  ExprResult r = run_fragment(
      "gl_FragColor = vec4(length(a.xyz), distance(a.xy, b.xy), dot(a, b), length(vec2(3.0, 4.0)));", interesting, second);
  expect_lanes(r, 0, [](int l) {
    float x = interesting(l, 0), y = interesting(l, 1), z = interesting(l, 2);
    return std::sqrt(z * z + (y * y + x * x));
  }, "length");
  expect_lanes(r, 1, [](int l) {
    float dx = interesting(l, 0) - second(l, 0), dy = interesting(l, 1) - second(l, 1);
    return std::sqrt(dy * dy + dx * dx);
  }, "distance");
  expect_lanes(r, 2, [](int l) {
    float s = interesting(l, 0) * second(l, 0);
    for (int c = 1; c < 4; ++c) s = interesting(l, c) * second(l, c) + s;
    return s;
  }, "dot");
  EXPECT_EQ(r.c[3][0], 5.0f);
}

TEST(BuiltinFunctions, CrossAndNormalize) {
  ExprResult r = run_fragment("gl_FragColor = vec4(cross(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0)), 0.0);", interesting);
  EXPECT_EQ(r.c[0][0], 0.0f);
  EXPECT_EQ(r.c[1][0], 0.0f);
  EXPECT_EQ(r.c[2][0], 1.0f);
  ExprResult c = run_fragment("gl_FragColor = vec4(cross(a.xyz, b.xyz), 0.0);", interesting, second);
  expect_lanes(c, 0, [](int l) { return interesting(l, 1) * second(l, 2) - interesting(l, 2) * second(l, 1); }, "cross x");
  expect_lanes(c, 2, [](int l) { return interesting(l, 0) * second(l, 1) - interesting(l, 1) * second(l, 0); }, "cross z");
  ExprResult n = run_fragment("gl_FragColor = vec4(normalize(vec3(a.x * 3.0, a.x * 4.0, 0.0)), 1.0);", interesting);
  EXPECT_FLOAT_EQ(n.c[0][2], 0.6f);
  EXPECT_FLOAT_EQ(n.c[1][2], 0.8f);
  // normalize of a zero vector gives zero (README.md), not NaN.
  EXPECT_EQ(n.c[0][0], 0.0f);
  EXPECT_EQ(n.c[1][0], 0.0f);
  EXPECT_EQ(n.c[2][0], 0.0f);
}

TEST(BuiltinFunctions, FaceforwardReflectRefract) {
  ExprResult f = run_fragment("gl_FragColor = vec4(faceforward(vec2(1.0, 2.0), vec2(a.x, 0.0), vec2(1.0, 0.0)), 0.0, 0.0);", interesting);
  expect_lanes(f, 0, [](int l) { return interesting(l, 0) < 0.0f ? 1.0f : -1.0f; }, "faceforward");
  expect_lanes(f, 1, [](int l) { return interesting(l, 0) < 0.0f ? 2.0f : -2.0f; }, "faceforward y");
  ExprResult r = run_fragment("gl_FragColor = vec4(reflect(vec2(1.0, -1.0), vec2(0.0, 1.0)), 0.0, 0.0);", interesting);
  EXPECT_EQ(r.c[0][0], 1.0f);
  EXPECT_EQ(r.c[1][0], 1.0f);
  // refract straight through with eta 1; total internal reflection gives zero.
  ExprResult t = run_fragment(
      "gl_FragColor = vec4(refract(vec2(0.0, -1.0), vec2(0.0, 1.0), 1.0), refract(normalize(vec2(1.0, -0.1)), vec2(0.0, 1.0), 2.0));",
      interesting);
  EXPECT_EQ(t.c[0][0], 0.0f);
  EXPECT_EQ(t.c[1][0], -1.0f);
  EXPECT_EQ(t.c[2][0], 0.0f);
  EXPECT_EQ(t.c[3][0], 0.0f);
}

TEST(BuiltinFunctions, VectorRelationalAnyAllNot) {
  ExprResult r = run_fragment(
      "bvec4 lt = lessThan(a, b);\n"
      "gl_FragColor = vec4(any(lt) ? 1.0 : 0.0, all(lt) ? 1.0 : 0.0, vec2(not(lt.xy)));",
      interesting, second);
  expect_lanes(r, 0, [](int l) {
    bool any = false;
    for (int c = 0; c < 4; ++c) any = any || interesting(l, c) < second(l, c);
    return any ? 1.0f : 0.0f;
  }, "any");
  expect_lanes(r, 1, [](int l) {
    bool all = true;
    for (int c = 0; c < 4; ++c) all = all && interesting(l, c) < second(l, c);
    return all ? 1.0f : 0.0f;
  }, "all");
  expect_lanes(r, 2, [](int l) { return interesting(l, 0) < second(l, 0) ? 0.0f : 1.0f; }, "not");
  ExprResult e = run_fragment(
      "gl_FragColor = vec4(vec2(equal(a.xy, b.xy)), vec2(greaterThanEqual(a.zw, b.zw)));", interesting, second);
  expect_lanes(e, 0, [](int l) { return interesting(l, 0) == second(l, 0) ? 1.0f : 0.0f; }, "equal");
  expect_lanes(e, 3, [](int l) { return interesting(l, 3) >= second(l, 3) ? 1.0f : 0.0f; }, "greaterThanEqual");
}

TEST(BuiltinFunctions, MatrixFunctions120) {
  ExprResult s = run_fragment(
      "mat2 m = matrixCompMult(mat2(1.0, 2.0, 3.0, 4.0), mat2(a.x));\n"
      "mat2x3 o = outerProduct(vec3(1.0, 2.0, 3.0), vec2(10.0, 20.0 * a.y));\n"
      "mat3x2 t = transpose(o);\n"
      "gl_FragColor = vec4(m[0][0], m[1][1], o[1][2], t[2][1]);",
      interesting, nullptr, "#version 120\n");
  expect_lanes(s, 0, [](int l) { return interesting(l, 0); }, "compmult 00");
  expect_lanes(s, 1, [](int l) { return 4.0f * interesting(l, 0); }, "compmult 11");
  expect_lanes(s, 2, [](int l) { return 3.0f * (20.0f * interesting(l, 1)); }, "outerProduct");
  expect_lanes(s, 3, [](int l) { return 3.0f * (20.0f * interesting(l, 1)); }, "transpose");
}

TEST(BuiltinFunctions, MatrixVectorProducts) {
  ExprResult s = run_fragment(
      "mat3 m = mat3(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, a.x);\n"
      "vec3 v = vec3(1.0, 10.0, 100.0);\n"
      "vec3 mv = m * v; vec3 vm = v * m; mat3 mm = m * m;\n"
      "gl_FragColor = vec4(mv.z, vm.z, mm[2][2], mm[0][1]);",
      interesting);
  expect_lanes(s, 0, [](int l) { return 3.0f + 60.0f + 100.0f * interesting(l, 0); }, "m*v");
  expect_lanes(s, 1, [](int l) { return 7.0f + 80.0f + 100.0f * interesting(l, 0); }, "v*m");
  expect_lanes(s, 2, [](int l) { float x = interesting(l, 0); return 3.0f * 7.0f + 6.0f * 8.0f + x * x; }, "m*m 22");
  expect_lanes(s, 3, [](int l) { return 1.0f * 2.0f + 2.0f * 5.0f + 3.0f * 8.0f; }, "m*m 01");
}

TEST(BuiltinFunctions, IntegerArithmeticTruncates) {
  ExprResult s = run_fragment(
      "int i = int(a.x * 4.0); int j = 3;\n"
      "gl_FragColor = vec4(float(i / j), float(-7 / j), float(i), float(ivec2(a.xy * 2.0).y));",
      interesting);
  expect_lanes(s, 0, [](int l) { return std::trunc(std::trunc(interesting(l, 0) * 4.0f) / 3.0f); }, "int div");
  expect_lanes(s, 1, [](int) { return -2.0f; }, "-7/3");
  expect_lanes(s, 2, [](int l) { return std::trunc(interesting(l, 0) * 4.0f); }, "int()");
  expect_lanes(s, 3, [](int l) { return std::trunc(interesting(l, 1) * 2.0f); }, "ivec2()");
}

TEST(BuiltinFunctions, NoiseIsZero) {
  ExprResult s = run_fragment("gl_FragColor = vec4(noise1(a.x), noise2(a.xy), noise1(a));", interesting);
  for (int c = 0; c < 4; ++c) expect_lanes(s, c, [](int) { return 0.0f; }, "noise");
}

}  // namespace
}  // namespace pineda::shader::test

namespace pineda::shader::test {
namespace {

TEST(BuiltinFunctions, DenormalsFlushToZero) {
  // 2^-75 * 2^-75 = 2^-150: zero after flushing (and after rounding); 2^-70 * 2^-70 = 2^-140
  // is a denormal in IEEE, zero here.
  ExprResult r = run_fragment("gl_FragColor = vec4(a.x * a.x > 0.0 ? 1.0 : 0.0, b.x * b.x > 0.0 ? 1.0 : 0.0, b.x * 1.0e20, 0.0);",
                              [](int, int) { return std::ldexp(1.0f, -75); }, [](int, int) { return std::ldexp(1.0f, -70); });
  EXPECT_EQ(r.c[0][0], 0.0f);
  EXPECT_EQ(r.c[1][0], 0.0f);
  EXPECT_EQ(r.c[2][0], std::ldexp(1.0f, -70) * 1.0e20f);
  // The caller's floating-point mode is left as it was.
  volatile float tiny = std::ldexp(1.0f, -70);
  volatile float product = tiny * tiny;
  EXPECT_GT(product, 0.0f);
}

}  // namespace
}  // namespace pineda::shader::test
