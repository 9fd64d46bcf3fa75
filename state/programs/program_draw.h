// Draws while a program is in use (GL 2.0 2.15): the vertex shader over batches of 16
// vertices, then clipping, setup and binning with the shader's varyings, and the fragment
// shader in the tiles.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "raster/draw_state.h"
#include "raster/vertex.h"
#include "state/programs/generic_attribs.h"
#include "state/transformed_vertices.h"

namespace pineda {

class Context;

// A draw's vertices as the vertex shader reads them: the vertices as fetched (`inputs`), or,
// when they are empty, the array element of each vertex (a shader reading generic attributes
// alone takes them straight from the arrays, AttribSource::Arrays).
struct ShaderVertices {
  std::span<const raster::VertexInput> inputs;
  std::span<const uint32_t> elements;
  size_t size() const { return inputs.empty() ? elements.size() : inputs.size(); }
};

// Draws with a program that has both stages; false when the program in use lacks one, so
// that the fixed-function path draws with the hooks below.
bool draw_with_program(Context& ctx, raster::Primitive primitive, const ShaderVertices& vertices,
                       std::span<const uint32_t> indices, AttribSource source);

// A program with a vertex shader only: the shader replaces transform and lighting. Its
// gl_Position, gl_FrontColor, gl_TexCoord[i], ... become `out` for the fixed-function
// fragment stage. False when the program in use is not such a program.
bool run_vertex_program_only(Context& ctx, std::span<const raster::VertexInput> vertices, AttribSource source,
                             TransformedVertices& transformed);

// A program with a fragment shader only: the fixed-function vertex stage produced
// `vertices`; their colours, texture coordinates and fog coordinate are the shader's inputs.
// False when the program in use is not such a program.
bool draw_fragment_program_only(Context& ctx, raster::Primitive primitive, std::span<const raster::ClipVertex> vertices,
                                std::span<const uint32_t> indices);

}  // namespace pineda
