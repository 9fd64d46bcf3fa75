// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]

#version 120

void main() {
	float f = 1.0f;
	gl_Position = vec4(1.0);
}
