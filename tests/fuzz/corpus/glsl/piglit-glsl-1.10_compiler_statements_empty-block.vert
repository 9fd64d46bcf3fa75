// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]

void main() {
	{}
	gl_Position = vec4(1.0);
}
