// The fuzzed debug output calls (KHR_debug: messages, the log, groups, object labels), by
// their desktop names and the KHR names that go to the same implementation. Strings are
// passed with their exact length and no terminator where the call takes a length, and every
// output has exactly bufSize bytes, so AddressSanitizer sees a read or write past either.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "tests/fuzz/es_prototypes.h"
#include "tests/fuzz/gl_calls.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kSources[] = {GL_DEBUG_SOURCE_API, GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_SOURCE_THIRD_PARTY,
                               GL_DEBUG_SOURCE_OTHER, GL_DONT_CARE};
constexpr GLenum kTypes[] = {GL_DEBUG_TYPE_ERROR, GL_DEBUG_TYPE_MARKER, GL_DEBUG_TYPE_OTHER,
                             GL_DEBUG_TYPE_PUSH_GROUP, GL_DONT_CARE};
constexpr GLenum kSeverities[] = {GL_DEBUG_SEVERITY_HIGH, GL_DEBUG_SEVERITY_NOTIFICATION, GL_DEBUG_SEVERITY_LOW,
                                  GL_DONT_CARE};
constexpr GLenum kIdentifiers[] = {GL_BUFFER, GL_SHADER, GL_PROGRAM, GL_QUERY, GL_TEXTURE, GL_RENDERBUFFER,
                                   GL_FRAMEBUFFER, GL_DISPLAY_LIST, GL_VERTEX_ARRAY, GL_SAMPLER};

// Text of a message or label: its bytes alone (no terminator) when `length` is given,
// terminated when it is negative; 0 to 1100 bytes, past the 1024 of GL_MAX_DEBUG_MESSAGE_LENGTH.
struct Text {
  std::vector<GLchar> bytes;
  GLsizei length;
};

Text text(FuzzInput& in) {
  const GLsizei size = in.integer(0, 1100) % 1101;
  Text t{std::vector<GLchar>(size_t(std::max(size, 0))), size};
  for (GLchar& c : t.bytes) c = GLchar('a' + c % 26);
  if (in.byte() % 4 == 0) {
    t.bytes.push_back('\0');
    t.length = -1;
  }
  return t;
}

const GLchar* text_data(const Text& t) { return t.bytes.empty() ? "" : t.bytes.data(); }

// A buffer of bufSize bytes (an address even for 0).
std::vector<GLchar> out_buffer(GLsizei size) { return std::vector<GLchar>(size_t(std::max(size, 0)) + (size <= 0)); }

void GLAPIENTRY ignore_message(GLenum, GLenum, GLuint, GLenum, GLsizei length, const GLchar* message, const void*) {
  // Reads the whole message: AddressSanitizer checks its terminator is where the length says.
  if (length >= 0 && std::strlen(message) != size_t(length)) __builtin_trap();
}

template <typename Call>
void message_control(FuzzInput& in, Call call) {
  const GLenum source = in.enumeration(kSources), type = in.enumeration(kTypes);
  const GLenum severity = in.enumeration(kSeverities);
  const GLuint ids[3] = {GLuint(in.integer(0, 8)), GLuint(in.integer(0, 8)), GLuint(in.integer(0, 8))};
  call(source, type, severity, std::min(in.bounded_size(3), 3), ids, in.boolean());
}

template <typename Call>
void message_insert(FuzzInput& in, Call call) {
  const GLenum source = in.enumeration(kSources), type = in.enumeration(kTypes);
  const GLuint id = GLuint(in.integer(0, 8));
  const GLenum severity = in.enumeration(kSeverities);
  const Text message = text(in);
  call(source, type, id, severity, message.length, text_data(message));
}

template <typename Call>
void message_callback(FuzzInput& in, Call call) {
  call(in.boolean() ? ignore_message : nullptr, nullptr);
}

// Up to 4 messages into arrays of 4 and a log of bufSize bytes; some arrays not asked for.
template <typename Call>
void message_log(FuzzInput& in, Call call) {
  const GLuint count = GLuint(std::min(in.integer(0, 4), 4));
  const GLsizei size = in.bounded_size(2100);
  std::vector<GLchar> log = out_buffer(size);
  GLenum sources[4], types[4], severities[4];
  GLuint ids[4];
  GLsizei lengths[4];
  const bool all = in.boolean();
  call(count, size, all ? sources : nullptr, types, all ? ids : nullptr, severities, all ? lengths : nullptr,
       in.boolean() ? log.data() : nullptr);
}

template <typename Call>
void push_group(FuzzInput& in, Call call) {
  const GLenum source = in.enumeration({GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_SOURCE_THIRD_PARTY, GL_DEBUG_SOURCE_API});
  const GLuint id = GLuint(in.integer(0, 8));
  const Text message = text(in);
  call(source, id, message.length, text_data(message));
}

template <typename Call>
void object_label(FuzzInput& in, Call call) {
  const GLenum identifier = in.enumeration(kIdentifiers);
  const GLuint name = in.name();
  const Text label = text(in);
  call(identifier, name, label.length, in.byte() % 8 == 0 ? nullptr : text_data(label));
}

template <typename Call>
void get_object_label(FuzzInput& in, Call call) {
  const GLenum identifier = in.enumeration(kIdentifiers);
  const GLuint name = in.name();
  const GLsizei size = in.bounded_size(1100);
  std::vector<GLchar> label = out_buffer(size);
  GLsizei length = 0;
  call(identifier, name, size, in.boolean() ? &length : nullptr, in.boolean() ? label.data() : nullptr);
}

// No sync objects exist in GL 2.1: a pointer to anything else must be rejected.
void* sync_pointer(FuzzInput& in, ClientMemory& memory) {
  return in.boolean() ? nullptr : memory.arrays.data() + in.offset(64);
}

template <typename Call>
void object_pointer_label(FuzzInput& in, ClientMemory& memory, Call call) {
  void* object = sync_pointer(in, memory);
  const Text label = text(in);
  call(object, label.length, text_data(label));
}

template <typename Call>
void get_object_pointer_label(FuzzInput& in, ClientMemory& memory, Call call) {
  void* object = sync_pointer(in, memory);
  const GLsizei size = in.bounded_size(64);
  std::vector<GLchar> label = out_buffer(size);
  GLsizei length = 0;
  call(object, size, &length, label.data());
}

const GlCall kCalls[] = {
    {"glEnable(debug output)",
     [](FuzzInput& in, ClientMemory&) { glEnable(in.enumeration({GL_DEBUG_OUTPUT, GL_DEBUG_OUTPUT_SYNCHRONOUS})); }},
    {"glDebugMessageControl", [](FuzzInput& in, ClientMemory&) { message_control(in, glDebugMessageControl); }},
    {"glDebugMessageControlKHR", [](FuzzInput& in, ClientMemory&) { message_control(in, glDebugMessageControlKHR); }},
    {"glDebugMessageInsert", [](FuzzInput& in, ClientMemory&) { message_insert(in, glDebugMessageInsert); }},
    {"glDebugMessageInsertKHR", [](FuzzInput& in, ClientMemory&) { message_insert(in, glDebugMessageInsertKHR); }},
    {"glDebugMessageCallback", [](FuzzInput& in, ClientMemory&) { message_callback(in, glDebugMessageCallback); }},
    {"glDebugMessageCallbackKHR",
     [](FuzzInput& in, ClientMemory&) { message_callback(in, glDebugMessageCallbackKHR); }},
    {"glGetDebugMessageLog", [](FuzzInput& in, ClientMemory&) { message_log(in, glGetDebugMessageLog); }},
    {"glGetDebugMessageLogKHR", [](FuzzInput& in, ClientMemory&) { message_log(in, glGetDebugMessageLogKHR); }},
    {"glPushDebugGroup", [](FuzzInput& in, ClientMemory&) { push_group(in, glPushDebugGroup); }},
    {"glPushDebugGroupKHR", [](FuzzInput& in, ClientMemory&) { push_group(in, glPushDebugGroupKHR); }},
    {"glPopDebugGroup", [](FuzzInput&, ClientMemory&) { glPopDebugGroup(); }},
    {"glPopDebugGroupKHR", [](FuzzInput&, ClientMemory&) { glPopDebugGroupKHR(); }},
    {"glObjectLabel", [](FuzzInput& in, ClientMemory&) { object_label(in, glObjectLabel); }},
    {"glObjectLabelKHR", [](FuzzInput& in, ClientMemory&) { object_label(in, glObjectLabelKHR); }},
    {"glGetObjectLabel", [](FuzzInput& in, ClientMemory&) { get_object_label(in, glGetObjectLabel); }},
    {"glGetObjectLabelKHR", [](FuzzInput& in, ClientMemory&) { get_object_label(in, glGetObjectLabelKHR); }},
    {"glObjectPtrLabel", [](FuzzInput& in, ClientMemory& m) { object_pointer_label(in, m, glObjectPtrLabel); }},
    {"glObjectPtrLabelKHR", [](FuzzInput& in, ClientMemory& m) { object_pointer_label(in, m, glObjectPtrLabelKHR); }},
    {"glGetObjectPtrLabel", [](FuzzInput& in, ClientMemory& m) { get_object_pointer_label(in, m, glGetObjectPtrLabel); }},
    {"glGetObjectPtrLabelKHR",
     [](FuzzInput& in, ClientMemory& m) { get_object_pointer_label(in, m, glGetObjectPtrLabelKHR); }},
    {"glGetPointervKHR",
     [](FuzzInput& in, ClientMemory&) {
       void* pointer = nullptr;
       glGetPointervKHR(in.enumeration({GL_DEBUG_CALLBACK_FUNCTION, GL_DEBUG_CALLBACK_USER_PARAM}), &pointer);
     }},
};

}  // namespace

std::span<const GlCall> debug_calls() { return kCalls; }

}  // namespace pineda::fuzz
