/* [config]
 * expect_result: pass
 * glsl_version: 1.20
 * [end config]
 *
 * Check that the following test vectors are constant folded correctly:
 * (false || false) => false
 * (false || true) => true
 * (true || false) => true
 * (true || true) => true
 */
#version 120

void main()
{
  float[(false || false) == false ? 1 : -1] array0;
  float[(false || true) == true ? 1 : -1] array1;
  float[(true || false) == true ? 1 : -1] array2;
  float[(true || true) == true ? 1 : -1] array3;
  gl_Position = vec4(array0.length() + array1.length() + array2.length() + array3.length());
}
