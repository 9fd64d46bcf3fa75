// Occlusion queries (GL 1.5, GL_ARB_occlusion_query): the draws between glBeginQuery and
// glEndQuery carry the query's counter down to the rasterizer.
#include <algorithm>
#include <cstdint>

#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

constexpr int kQueryCounterBits = 64;

void stop_counting(Context& ctx) {
  ctx.queries.active_samples_passed.reset();
  ctx.draw_state.sample_counter.reset();
}

// The finished query `id`, or null (GL_INVALID_OPERATION recorded).
QueryObject* finished_query(Context& ctx, GLuint id) {
  std::shared_ptr<QueryObject> q = ctx.queries.names.find(id);
  if (!q || q == ctx.queries.active_samples_passed) {
    ctx.record_error(GL_INVALID_OPERATION, "id is not a query object or is the active query");
    return nullptr;
  }
  return q.get();
}

// Result of query `id` for `pname`; false when an error was recorded.
bool query_result(Context& ctx, GLuint id, GLenum pname, uint64_t& out) {
  if (pname != GL_QUERY_RESULT && pname != GL_QUERY_RESULT_AVAILABLE) {
    ctx.record_error(GL_INVALID_ENUM, "pname is not GL_QUERY_RESULT or GL_QUERY_RESULT_AVAILABLE");
    return false;
  }
  QueryObject* q = finished_query(ctx, id);
  if (!q) return false;
  ctx.finish_for_reading();  // the queued draws have counted: the result is available from here on
  out = pname == GL_QUERY_RESULT_AVAILABLE ? GL_TRUE : (q->counter ? q->counter->passed.load() : 0);
  return true;
}

}  // namespace

void GenQueries(Context& ctx, GLsizei n, GLuint* ids) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (ids) ctx.queries.names.generate(n, ids);
}

void DeleteQueries(Context& ctx, GLsizei n, const GLuint* ids) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (!ids) return;
  for (GLsizei i = 0; i < n; ++i) {
    if (ids[i] == 0) continue;
    if (ctx.queries.active_samples_passed && ctx.queries.active_samples_passed->name == ids[i]) stop_counting(ctx);
    ctx.queries.names.remove(ids[i]);
    ctx.debug.forget_label(GL_QUERY, ids[i]);
  }
}

GLboolean IsQuery(Context& ctx, GLuint id) { return ctx.queries.names.exists(id) ? GL_TRUE : GL_FALSE; }

void BeginQuery(Context& ctx, GLenum target, GLuint id) {
  if (target != GL_SAMPLES_PASSED) return ctx.record_error(GL_INVALID_ENUM, "target is not GL_SAMPLES_PASSED");
  if (id == 0) return ctx.record_error(GL_INVALID_OPERATION, "id is zero");
  if (ctx.queries.active_samples_passed)
    return ctx.record_error(GL_INVALID_OPERATION, "a query of target is already active");
  const std::shared_ptr<QueryObject>& q = ctx.queries.names.get_or_create(id);
  q->counter = std::make_shared<raster::SampleCounter>();
  ctx.queries.active_samples_passed = q;
  ctx.draw_state.sample_counter = q->counter;
}

void EndQuery(Context& ctx, GLenum target) {
  if (target != GL_SAMPLES_PASSED) return ctx.record_error(GL_INVALID_ENUM, "target is not GL_SAMPLES_PASSED");
  if (!ctx.queries.active_samples_passed) return ctx.record_error(GL_INVALID_OPERATION, "no query of target is active");
  stop_counting(ctx);
}

void GetQueryiv(Context& ctx, GLenum target, GLenum pname, GLint* params) {
  if (target != GL_SAMPLES_PASSED) return ctx.record_error(GL_INVALID_ENUM, "target is not GL_SAMPLES_PASSED");
  GLint value = 0;
  switch (pname) {
    case GL_CURRENT_QUERY:
      value = ctx.queries.active_samples_passed ? GLint(ctx.queries.active_samples_passed->name) : 0;
      break;
    case GL_QUERY_COUNTER_BITS: value = kQueryCounterBits; break;
    default: return ctx.record_error(GL_INVALID_ENUM, "pname is not GL_CURRENT_QUERY or GL_QUERY_COUNTER_BITS");
  }
  if (params) *params = value;
}

void GetQueryObjectiv(Context& ctx, GLuint id, GLenum pname, GLint* params) {
  uint64_t v = 0;
  if (query_result(ctx, id, pname, v) && params) *params = GLint(std::min<uint64_t>(v, INT32_MAX));
}

void GetQueryObjectuiv(Context& ctx, GLuint id, GLenum pname, GLuint* params) {
  uint64_t v = 0;
  if (query_result(ctx, id, pname, v) && params) *params = GLuint(std::min<uint64_t>(v, UINT32_MAX));
}

// The ARB_occlusion_query names.
void GenQueriesARB(Context& ctx, GLsizei n, GLuint* ids) { GenQueries(ctx, n, ids); }
void DeleteQueriesARB(Context& ctx, GLsizei n, const GLuint* ids) { DeleteQueries(ctx, n, ids); }
GLboolean IsQueryARB(Context& ctx, GLuint id) { return IsQuery(ctx, id); }
void BeginQueryARB(Context& ctx, GLenum target, GLuint id) { BeginQuery(ctx, target, id); }
void EndQueryARB(Context& ctx, GLenum target) { EndQuery(ctx, target); }
void GetQueryivARB(Context& ctx, GLenum target, GLenum pname, GLint* params) { GetQueryiv(ctx, target, pname, params); }
void GetQueryObjectivARB(Context& ctx, GLuint id, GLenum pname, GLint* params) {
  GetQueryObjectiv(ctx, id, pname, params);
}
void GetQueryObjectuivARB(Context& ctx, GLuint id, GLenum pname, GLuint* params) {
  GetQueryObjectuiv(ctx, id, pname, params);
}

}  // namespace pineda::gl
