/// @file mesh.hpp
/// Reading the vertices of a mesh file (Wavefront OBJ, STL ASCII or binary) as a point set, for
/// build_convex_hull(). Only positions are kept: every vertex of the file, whether or not a face
/// uses it, because the hull of a mesh is the hull of its vertices. Coordinates are returned in
/// the file's own unit and frame, unchanged (binary STL floats are widened to double exactly).
///
/// A strict reader of our own, not a library: Debian 12's tinyobjloader (2.0.0~rc10) reads
/// "nan", "abc" and missing coordinates as 0 and reports out-of-range face indices only as a
/// warning, so a damaged file would give a plausible wrong hull; assimp (libassimp-dev) pulls in
/// a large dependency tree for two formats whose grammar fits in this file, and Debian has no
/// STL-only library. A mesh reader that guesses is worse than none for a hull: a point silently
/// moved to 0 changes the answer. So every line is checked, and the first problem is an error.
///
/// What is accepted:
///   - OBJ: `v x y z [w]` (and the common `v x y z r g b` colour extension); `vn`, `vt`, `vp`
///     (numbers checked, otherwise ignored); `f`, `l`, `p` with `v`, `v/vt`, `v//vn`, `v/vt/vn`
///     references, 1-based or negative (relative to the vertices read so far), each checked
///     against the number of vertices (normals, texture coordinates) the file defines; `#`
///     comments; the other statements of the OBJ specification (`o`, `g`, `s`, `usemtl`,
///     `mtllib`, free-form geometry keywords) are skipped. An unknown statement is an error.
///   - STL binary: an 80-byte header, a little-endian uint32 triangle count n, then n records
///     of 50 bytes; the file must be exactly 84 + 50 n bytes. It is recognised by that size,
///     even when its header begins with "solid" (many exporters write that).
///   - STL ASCII: `solid [name]`, facets `facet normal nx ny nz` / `outer loop` / three
///     `vertex x y z` / `endloop` / `endfacet`, `endsolid [name]`; several solids may follow
///     each other. Keywords are case-insensitive.
/// Both: lines may end in CRLF; numbers are decimal floating point ("1", "-2.5e-3", "+.5").
///
/// Errors (the Expected's reason; `name:line: what` for text, `name: triangle k: what` for
/// binary STL): a file that cannot be opened or read, an unknown statement, a malformed or
/// out-of-range number, a NaN or infinite coordinate (normals of STL facets may be anything:
/// they are not used), a wrong number of fields, a face index that is 0 or out of range, a
/// binary STL whose size does not match its triangle count (truncated), an ASCII STL out of
/// grammar, and a file with no vertex at all.
///
/// Cost: one pass over the bytes; the file is read into memory whole. Reentrant, no global state.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "mink/expected.hpp"
#include "mink/math/vec.hpp"

namespace mink {

/// The file formats read_mesh_points() understands.
enum class MeshFormat {
  Auto,  ///< decide from the content: a binary STL by its size, an ASCII STL by "solid", else OBJ
  Obj,   ///< Wavefront OBJ
  Stl,   ///< STL, binary or ASCII (told apart by the size and the content)
};

/// The vertices of the mesh file at `path`. The format comes from the extension (`.obj`,
/// `.stl`, any case), else from the content (MeshFormat::Auto). Errors: see the file comment;
/// every message begins with `path`.
Expected<std::vector<Vec3>> read_mesh_points(const std::string& path);

/// The same from bytes already in memory; `name` only labels the error messages.
Expected<std::vector<Vec3>> parse_mesh_points(std::string_view bytes, MeshFormat format,
                                              std::string_view name = "mesh");

}  // namespace mink
