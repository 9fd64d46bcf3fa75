/* [config]
 * expect_result: pass
 * glsl_version: 1.20
 * [end config]
 *
 * Check that the following test vectors are constant folded correctly:
 * notEqual(bvec2(false, false), bvec2(false, true)) => bvec2(false, true)
 * notEqual(bvec2(true, true), bvec2(false, true)) => bvec2(true, false)
 */
#version 120

void main()
{
  float[all(equal(notEqual(bvec2(false, false), bvec2(false, true)), bvec2(false, true))) ? 1 : -1] array0;
  float[all(equal(notEqual(bvec2(true, true), bvec2(false, true)), bvec2(true, false))) ? 1 : -1] array1;
  gl_Position = vec4(array0.length() + array1.length());
}
