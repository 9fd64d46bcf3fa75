/* [config]
 * expect_result: pass
 * glsl_version: 1.20
 * [end config]
 *
 * Check that the following test vectors are constant folded correctly:
 * inversesqrt(vec4(0.1, 0.73333335, 1.3666667, 2.0)) => vec4(3.1622777, 1.1677485, 0.8553989, 0.70710677)
 */
#version 120

void main()
{
  float[distance(inversesqrt(vec4(0.1, 0.73333335, 1.3666667, 2.0)), vec4(3.1622777, 1.1677485, 0.8553989, 0.70710677)) <= 3.548992e-05 ? 1 : -1] array0;
  gl_Position = vec4(array0.length());
}
