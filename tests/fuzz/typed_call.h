// Table entries for calls whose arguments are numbers or arrays of numbers (glColor3s,
// glVertex4dv, glRasterPos2i, glLoadMatrixd, glVertexAttrib4Nubv ...), optionally after one
// enum: each argument is drawn by its type, so one line names the call and nothing else.
#pragma once
#include <GL/gl.h>

#include <span>
#include <tuple>
#include <type_traits>
#include <vector>

#include "tests/fuzz/gl_calls.h"

namespace pineda::fuzz {

// A number: reals (NaN, infinities, 1e30 among them) for floating point, small or extreme
// integers (GLfixed is a GLint) otherwise.
template <typename T>
struct DrawnArgument {
  T value;
  explicit DrawnArgument(FuzzInput& in) {
    if constexpr (std::is_floating_point_v<T>) value = T(in.real());
    else value = T(in.integer(-4, 40));
  }
  T get() const { return value; }
};

// An array: 16 drawn numbers, the most any such call reads (a matrix), in memory of its own
// so that AddressSanitizer sees a read past them.
template <typename T>
struct DrawnArgument<const T*> {
  std::vector<T> values;
  explicit DrawnArgument(FuzzInput& in) : values(16) {
    for (T& v : values) v = DrawnArgument<T>(in).value;
  }
  const T* get() const { return values.data(); }
};

// Draws the arguments A... (braces: left to right) and hands them to `call`.
template <typename... A, typename Call>
void with_drawn_arguments(FuzzInput& in, Call&& call) {
  const std::tuple<DrawnArgument<A>...> drawn{DrawnArgument<A>(in)...};
  std::apply([&](const auto&... a) { call(a.get()...); }, drawn);
}

template <typename R, typename... A>
void call_with_drawn_arguments(R (*call)(A...), FuzzInput& in) {
  with_drawn_arguments<A...>(in, call);
}

template <typename R, typename... A>
void call_with_drawn_arguments(R (*call)(GLenum, A...), GLenum first, FuzzInput& in) {
  with_drawn_arguments<A...>(in, [&](A... a) { call(first, a...); });
}

template <typename R, typename... A>
void call_with_drawn_arguments(R (*call)(GLenum, GLenum, A...), GLenum first, GLenum second, FuzzInput& in) {
  with_drawn_arguments<A...>(in, [&](A... a) { call(first, second, a...); });
}

template <auto Call>
constexpr GlCall typed_call(const char* name) {
  return {name, [](FuzzInput& in, ClientMemory&) { call_with_drawn_arguments(Call, in); }};
}

// The first argument one of `kFirst` (a texture unit, a light model parameter ...).
template <auto Call, const auto& kFirst>
constexpr GlCall typed_call_after_enum(const char* name) {
  return {name, [](FuzzInput& in, ClientMemory&) {
            const GLenum first = in.enumeration(std::span<const GLenum>(kFirst));
            call_with_drawn_arguments(Call, first, in);
          }};
}

// The first two arguments one of `kFirst` and one of `kSecond` (a light and its parameter ...).
template <auto Call, const auto& kFirst, const auto& kSecond>
constexpr GlCall typed_call_after_enums(const char* name) {
  return {name, [](FuzzInput& in, ClientMemory&) {
            const GLenum first = in.enumeration(std::span<const GLenum>(kFirst));
            const GLenum second = in.enumeration(std::span<const GLenum>(kSecond));
            call_with_drawn_arguments(Call, first, second, in);
          }};
}

}  // namespace pineda::fuzz

// Entries named after their call.
#define PINEDA_TYPED_CALL(call) ::pineda::fuzz::typed_call<call>(#call)
#define PINEDA_TYPED_CALL_AFTER(call, first) ::pineda::fuzz::typed_call_after_enum<call, first>(#call)
#define PINEDA_TYPED_CALL_AFTER2(call, first, second) \
  ::pineda::fuzz::typed_call_after_enums<call, first, second>(#call)
