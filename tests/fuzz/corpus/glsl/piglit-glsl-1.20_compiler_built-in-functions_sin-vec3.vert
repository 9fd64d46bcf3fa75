/* [config]
 * expect_result: pass
 * glsl_version: 1.20
 * [end config]
 *
 * Check that the following test vectors are constant folded correctly:
 * sin(vec3(-3.1415927, -1.0471976, 1.0471976)) => vec3(8.742278e-08, -0.86602545, 0.86602545)
 * sin(vec3(3.1415927, -3.1415927, -1.0471976)) => vec3(-8.742278e-08, 8.742278e-08, -0.86602545)
 */
#version 120

void main()
{
  float[distance(sin(vec3(-3.1415927, -1.0471976, 1.0471976)), vec3(8.742278e-08, -0.86602545, 0.86602545)) <= 0.0012288205 ? 1 : -1] array0;
  float[distance(sin(vec3(3.1415927, -3.1415927, -1.0471976)), vec3(-8.742278e-08, 8.742278e-08, -0.86602545)) <= 0.00087749644 ? 1 : -1] array1;
  gl_Position = vec4(array0.length() + array1.length());
}
