/* [config]
 * expect_result: fail
 * glsl_version: 1.10
 * [end config]
 */
#version 999

void main()
{
    gl_Position = vec4(0.);
}
