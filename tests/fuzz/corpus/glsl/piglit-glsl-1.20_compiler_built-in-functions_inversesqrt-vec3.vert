/* [config]
 * expect_result: pass
 * glsl_version: 1.20
 * [end config]
 *
 * Check that the following test vectors are constant folded correctly:
 * inversesqrt(vec3(0.1, 0.73333335, 1.3666667)) => vec3(3.1622777, 1.1677485, 0.8553989)
 * inversesqrt(vec3(2.0, 0.1, 0.73333335)) => vec3(0.70710677, 3.1622777, 1.1677485)
 */
#version 120

void main()
{
  float[distance(inversesqrt(vec3(0.1, 0.73333335, 1.3666667)), vec3(3.1622777, 1.1677485, 0.8553989)) <= 3.477836e-05 ? 1 : -1] array0;
  float[distance(inversesqrt(vec3(2.0, 0.1, 0.73333335)), vec3(0.70710677, 3.1622777, 1.1677485)) <= 3.444363e-05 ? 1 : -1] array1;
  gl_Position = vec4(array0.length() + array1.length());
}
