/* [config]
 * expect_result: pass
 * glsl_version: 1.20
 * [end config]
 *
 * Check that the following test vectors are constant folded correctly:
 * mod(vec2(-1.9, -0.6333333), -2.0) => vec2(-1.9, -0.6333333)
 * mod(vec2(0.6333333, 1.9), -2.0) => vec2(-1.3666667, -0.100000024)
 * mod(vec2(-1.9, -0.6333333), -0.6666667) => vec2(-0.5666666, -0.6333333)
 * mod(vec2(0.6333333, 1.9), -0.6666667) => vec2(-0.03333336, -0.10000008)
 * mod(vec2(-1.9, -0.6333333), 0.6666667) => vec2(0.10000008, 0.03333336)
 * mod(vec2(0.6333333, 1.9), 0.6666667) => vec2(0.6333333, 0.5666666)
 * mod(vec2(-1.9, -0.6333333), 2.0) => vec2(0.100000024, 1.3666667)
 * mod(vec2(0.6333333, 1.9), 2.0) => vec2(0.6333333, 1.9)
 */
#version 120

void main()
{
  float[distance(mod(vec2(-1.9, -0.6333333), -2.0), vec2(-1.9, -0.6333333)) <= 2.0027757e-05 ? 1 : -1] array0;
  float[distance(mod(vec2(0.6333333, 1.9), -2.0), vec2(-1.3666667, -0.100000024)) <= 1.3703203e-05 ? 1 : -1] array1;
  float[distance(mod(vec2(-1.9, -0.6333333), -0.6666667), vec2(-0.5666666, -0.6333333)) <= 8.498366e-06 ? 1 : -1] array2;
  float[distance(mod(vec2(0.6333333, 1.9), -0.6666667), vec2(-0.03333336, -0.10000008)) <= 1.0540934e-06 ? 1 : -1] array3;
  float[distance(mod(vec2(-1.9, -0.6333333), 0.6666667), vec2(0.10000008, 0.03333336)) <= 1.0540934e-06 ? 1 : -1] array4;
  float[distance(mod(vec2(0.6333333, 1.9), 0.6666667), vec2(0.6333333, 0.5666666)) <= 8.498366e-06 ? 1 : -1] array5;
  float[distance(mod(vec2(-1.9, -0.6333333), 2.0), vec2(0.100000024, 1.3666667)) <= 1.3703203e-05 ? 1 : -1] array6;
  float[distance(mod(vec2(0.6333333, 1.9), 2.0), vec2(0.6333333, 1.9)) <= 2.0027757e-05 ? 1 : -1] array7;
  gl_Position = vec4(array0.length() + array1.length() + array2.length() + array3.length() + array4.length() + array5.length() + array6.length() + array7.length());
}
