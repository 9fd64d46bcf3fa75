/* [config]
 * expect_result: pass
 * glsl_version: 1.20
 * [end config]
 *
 * Check that the following test vectors are constant folded correctly:
 * cos(vec3(-3.1415927, -1.0471976, 1.0471976)) => vec3(-1.0, 0.49999997, 0.49999997)
 * cos(vec3(3.1415927, -3.1415927, -1.0471976)) => vec3(-1.0, -1.0, 0.49999997)
 */
#version 120

void main()
{
  float[distance(cos(vec3(-3.1415927, -1.0471976, 1.0471976)), vec3(-1.0, 0.49999997, 0.49999997)) <= 0.001224745 ? 1 : -1] array0;
  float[distance(cos(vec3(3.1415927, -3.1415927, -1.0471976)), vec3(-1.0, -1.0, 0.49999997)) <= 0.0015000001 ? 1 : -1] array1;
  gl_Position = vec4(array0.length() + array1.length());
}
