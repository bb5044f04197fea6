// Mesh input (io/mesh.hpp): OBJ, ASCII STL and binary STL files written here byte by byte give
// exactly the vertices they list, in order; every kind of broken file gives an error that names
// the file and, for text, the line.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mink/hull/convex_hull.hpp"
#include "mink/io/mesh.hpp"

namespace {

using mink::MeshFormat;
using mink::Vec3;

/// A scratch file under the test's temporary directory, with the given bytes.
std::string write_file(const std::string& name, const std::string& bytes) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "mink_mesh_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  return path;
}

void expect_points(const mink::Expected<std::vector<Vec3>>& result,
                   const std::vector<Vec3>& expected) {
  ASSERT_TRUE(result) << result.error();
  ASSERT_EQ(result->size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ((*result)[i], expected[i]) << "point " << i;  // exact: decimal in, double out
}

/// The error of a read that must fail, after checking that it failed.
std::string error_of(const mink::Expected<std::vector<Vec3>>& result) {
  EXPECT_FALSE(result) << "read " << (result ? result->size() : 0) << " points";
  return result ? std::string() : result.error();
}

// --- binary STL, built byte by byte (little-endian, as the format says) ---

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xFF);
}
void put_float(std::string& out, float f) {
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  put_u32(out, bits);
}

/// A binary STL of `triangles` (3 vertices each); `header` fills the 80-byte header.
std::string binary_stl(const std::vector<std::array<std::array<float, 3>, 3>>& triangles,
                       const std::string& header = "binary mesh") {
  std::string out = header;
  out.resize(80, ' ');
  put_u32(out, std::uint32_t(triangles.size()));
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) put_float(out, 0.0f);  // normal: unused
    for (const auto& v : t)
      for (float c : v) put_float(out, c);
    out += '\0';
    out += '\0';
  }
  return out;
}

/// The 12 triangles of the cube [0, 2]^3 as an ASCII STL (normals deliberately left 0).
std::string ascii_stl_cube() {
  const std::array<std::array<int, 3>, 8> c = {
      {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}}};
  const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                            {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::string out = "solid cube\n";
  for (const auto& f : faces) {
    out += "  facet normal 0 0 0\n    outer loop\n";
    for (int v : f)
      out += "      vertex " + std::to_string(c[v][0]) + " " + std::to_string(c[v][1]) + " " +
             std::to_string(c[v][2]) + "\n";
    out += "    endloop\n  endfacet\n";
  }
  out += "endsolid cube\n";
  return out;
}

TEST(MeshObj, ReadsEveryVertexWithCommentsNormalsTexturesAndNegativeIndices) {
  const std::string obj =
      "\xEF\xBB\xBF# a unit tetrahedron and a stray vertex\r\n"
      "mtllib scene.mtl\n"
      "o tet\n"
      "v 0 0 0\n"
      "v 1.5 0 0   # trailing comment\n"
      "v +0 2.25 -0\n"
      "v 0 0 -3e-1 1.0\n"      // with a weight w
      "v 7 8 9 0.5 0.5 0.5\n"  // with a colour; referenced by no face, still a vertex
      "vt 0 0\nvt 1 0\nvt 0 1\n"
      "vn 0 0 1\n"
      "g side\nusemtl red\ns off\n"
      "f 1/1/1 2/2/1 3/3/1\n"
      "f -4//-1 -3//1 -2//1\n"
      "f 1 2 4 3\n"
      "l 1 2\n"
      "p -1\n"
      "\n";
  expect_points(mink::parse_mesh_points(obj, MeshFormat::Obj, "t.obj"),
                {{0, 0, 0}, {1.5, 0, 0}, {0, 2.25, 0}, {0, 0, -0.3}, {7, 8, 9}});
  // The same bytes through a file, the format from the extension (any case), and from the
  // content when the extension says nothing.
  expect_points(mink::read_mesh_points(write_file("t.OBJ", obj)),
                {{0, 0, 0}, {1.5, 0, 0}, {0, 2.25, 0}, {0, 0, -0.3}, {7, 8, 9}});
  expect_points(mink::read_mesh_points(write_file("t.mesh", obj)),
                {{0, 0, 0}, {1.5, 0, 0}, {0, 2.25, 0}, {0, 0, -0.3}, {7, 8, 9}});
}

TEST(MeshObj, ForwardPositiveIndicesAreCheckedAgainstTheWholeFile) {
  // Some writers put faces first; a positive index is valid if the file defines the vertex.
  expect_points(mink::parse_mesh_points("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", MeshFormat::Obj),
                {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
}

TEST(MeshObj, BrokenFilesSayWhatAndWhichLine) {
  struct Case {
    const char* text;
    const char* expected;  ///< a fragment the message must contain
  };
  const Case cases[] = {
      {"v 0 0 0\nv 1 abc 0\n", "bad.obj:2: v coordinate y 'abc' is not a number"},
      {"v 0 0 0\nv 1 2\n", "bad.obj:2: v needs x y z"},
      {"v 0 0 0 0 0\n", "bad.obj:1: v needs x y z"},
      {"v nan 0 0\n", "bad.obj:1: v coordinate x 'nan' is not finite"},
      {"v 0 inf 0\n", "bad.obj:1: v coordinate y 'inf' is not finite"},
      {"v 0 0 -infinity\n", "bad.obj:1: v coordinate z '-infinity' is not finite"},
      {"v 0 0 1e999\n", "bad.obj:1: v coordinate z '1e999' is out of the range of a double"},
      {"v 1.5.2 0 0\n", "is not a number"},
      {"v +-1 0 0\n", "'+-1' is not a number"},
      {"v 0x10 0 0\n", "'0x10' is not a number"},
      {"v 1,5 0 0\n", "bad.obj:1: v coordinate x '1,5' is not a number"},
      {"vn 0 0\n", "bad.obj:1: vn needs 3 numbers, found 2"},
      {"vt 0 q\n", "bad.obj:1: vt value 2 'q' is not a number"},
      {"# nothing\n\ng empty\n", "bad.obj: no vertices"},
      {"", "bad.obj: no vertices"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\nf 1 2 3\n",
       "bad.obj:5: refers to vertex 9, but the file defines 3"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n",
       "bad.obj:4: index -4 in '-4' reaches before the first of the 3 vertex defined so far"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "bad.obj:4: index 0 in '0'"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n",
       "bad.obj:5: refers to texture coordinate 2, but the file defines 1"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n",
       "bad.obj:4: refers to normal 1, but the file defines 0"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", "has more than three parts"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", "bad.obj:4: index 'x' in 'x' is not an integer"},
      {"v 0 0 0\nv 1 0 0\nf 1 2\n", "bad.obj:3: f needs at least 3 vertices, found 2"},
      {"v 0 0 0\nv 1 0 0\nf 1/ 2 1\n", "bad.obj:3: index '' in '1/' is not an integer"},
      {"v 0 0 0\nbogus 1 2\n", "bad.obj:2: unknown statement 'bogus'"},
      {"v 0 0 \\\n 0\n", "bad.obj:1: line continuation"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string message =
        error_of(mink::parse_mesh_points(c.text, MeshFormat::Obj, "bad.obj"));
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

TEST(MeshStl, AsciiCubeGivesItsVerticesAndTheirHull) {
  const auto points = mink::read_mesh_points(write_file("cube.stl", ascii_stl_cube()));
  ASSERT_TRUE(points) << points.error();
  ASSERT_EQ(points->size(), 36u);  // 12 facets, 3 vertices each, repeated as the file has them
  EXPECT_EQ((*points)[0], Vec3(0, 0, 0));
  EXPECT_EQ((*points)[1], Vec3(2, 2, 0));
  EXPECT_EQ((*points)[35], Vec3(0, 2, 2));
  const auto hull = mink::build_convex_hull(*points);
  ASSERT_TRUE(hull) << hull.error();
  EXPECT_EQ(hull->vertices.size(), 8u);
  EXPECT_EQ(hull->faces.size(), 6u);
  EXPECT_NEAR(hull->volume, 8.0, 1e-12);  // side 2
  EXPECT_NEAR(hull->area, 24.0, 1e-12);
}

TEST(MeshStl, AsciiAcceptsAnyCaseSeveralSolidsAndNanNormals) {
  const std::string stl =
      "SOLID one\r\n FACET NORMAL nan nan nan\r\n OUTER LOOP\r\n VERTEX 1 2 3\r\n"
      " VERTEX 4 5 6\r\n VERTEX 7 8 9.5\r\n ENDLOOP\r\n ENDFACET\r\nENDSOLID one\r\n"
      "solid\nfacet normal 0 0 1\nouter loop\nvertex -1 -2 -3\nvertex 0 0 0\nvertex 1e-3 0 0\n"
      "endloop\nendfacet\nendsolid\n";
  expect_points(mink::parse_mesh_points(stl, MeshFormat::Stl),
                {{1, 2, 3}, {4, 5, 6}, {7, 8, 9.5}, {-1, -2, -3}, {0, 0, 0}, {1e-3, 0, 0}});
  expect_points(mink::parse_mesh_points(stl, MeshFormat::Auto),
                {{1, 2, 3}, {4, 5, 6}, {7, 8, 9.5}, {-1, -2, -3}, {0, 0, 0}, {1e-3, 0, 0}});
}

TEST(MeshStl, BrokenAsciiFilesSayWhatAndWhichLine) {
  const std::string head = "solid s\nfacet normal 0 0 1\nouter loop\n";
  struct Case {
    std::string text;
    const char* expected;
  };
  const Case cases[] = {
      {head + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n",
       "bad.stl:7: a facet has more than 3 vertices"},
      {head + "vertex 0 0 0\nvertex 1 0 0\nendloop\n", "bad.stl:6: a facet has 2 vertices"},
      {head + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 nan 0\n",
       "bad.stl:6: vertex coordinate y 'nan' is not finite"},
      {head + "vertex 0 0 0\nvertex 1 0\n", "bad.stl:5: vertex needs 3 numbers, found 2"},
      {head + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n",
       "bad.stl:8: unexpected end of file: expected 'facet normal' or 'endsolid' (truncated"},
      {head + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendsolid s\n",
       "bad.stl:8: expected 'endfacet', found 'endsolid'"},
      {"solid s\nfacet 0 0 1\n", "bad.stl:2: expected 'facet normal nx ny nz'"},
      {"solid s\nfacet normal 0 zero 1\n", "bad.stl:2: facet normal coordinate y 'zero'"},
      {"solid s\nendsolid s\n", "bad.stl: no vertices (ASCII STL without facets)"},
      {"solid s\nendsolid s\ngarbage\n", "bad.stl:3: expected 'solid' or the end of the file"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string message =
        error_of(mink::parse_mesh_points(c.text, MeshFormat::Stl, "bad.stl"));
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

TEST(MeshStl, BinaryGivesTheFloatsExactly) {
  // Floats that are not short decimals: the reader must widen them exactly.
  const float third = 1.0f / 3.0f;
  const std::vector<std::array<std::array<float, 3>, 3>> triangles = {
      {{{0, 0, 0}, {1, 0, 0}, {0, third, 0}}},
      {{{-2.5f, 1e-20f, 3e20f}, {0.1f, 0.2f, 0.3f}, {-0.0f, 7, 8}}}};
  const std::vector<Vec3> expected = {{0, 0, 0},
                                      {1, 0, 0},
                                      {0, double(third), 0},
                                      {-2.5, double(1e-20f), double(3e20f)},
                                      {double(0.1f), double(0.2f), double(0.3f)},
                                      {0, 7, 8}};
  expect_points(mink::read_mesh_points(write_file("tri.stl", binary_stl(triangles))), expected);
  // A header beginning with "solid", as many exporters write: still binary, told by its size.
  const std::string solid_header = binary_stl(triangles, "solid exported by some tool");
  expect_points(mink::read_mesh_points(write_file("solid.stl", solid_header)), expected);
  expect_points(mink::parse_mesh_points(solid_header, MeshFormat::Auto), expected);
}

TEST(MeshStl, BrokenBinaryFilesSayWhatAndWhere) {
  const std::vector<std::array<std::array<float, 3>, 3>> one = {
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}};
  const std::string good = binary_stl(one);
  ASSERT_EQ(good.size(), 134u);  // 84 + 50

  // Truncated: the count says 1 triangle, 20 bytes are missing.
  std::string message =
      error_of(mink::parse_mesh_points(good.substr(0, 114), MeshFormat::Stl, "cut.stl"));
  EXPECT_NE(message.find("cut.stl: binary STL of 1 triangles should have 84 + 50 * 1 = 134 bytes, "
                         "but has 114 (truncated)"),
            std::string::npos)
      << message;
  // The same with a "solid" header: the NUL bytes show it is not text.
  message = error_of(mink::parse_mesh_points(binary_stl(one, "solid x").substr(0, 120),
                                             MeshFormat::Stl, "cut.stl"));
  EXPECT_NE(message.find("(truncated)"), std::string::npos) << message;
  // Trailing bytes.
  message = error_of(mink::parse_mesh_points(good + "xx", MeshFormat::Stl, "long.stl"));
  EXPECT_NE(message.find("but has 136"), std::string::npos) << message;
  // Shorter than a header.
  message = error_of(mink::parse_mesh_points("hello", MeshFormat::Stl, "short.stl"));
  EXPECT_NE(message.find("short.stl: not an STL file"), std::string::npos) << message;
  // No triangles.
  message = error_of(mink::parse_mesh_points(binary_stl({}), MeshFormat::Stl, "empty.stl"));
  EXPECT_NE(message.find("empty.stl: no vertices"), std::string::npos) << message;
  // A NaN and an infinite coordinate.
  for (const float bad :
       {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    const std::vector<std::array<std::array<float, 3>, 3>> two = {
        {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{0, 0, 0}, {1, 0, bad}, {0, 1, 0}}}};
    message = error_of(mink::parse_mesh_points(binary_stl(two), MeshFormat::Stl, "nan.stl"));
    EXPECT_NE(message.find("nan.stl: triangle 2 (byte 134): vertex 2 has a NaN or infinite "
                           "coordinate"),
              std::string::npos)
        << message;
  }
}

TEST(MeshFile, UnreadableFilesSayWhy) {
  const std::string missing = ::testing::TempDir() + "/mink_mesh_test/does_not_exist.obj";
  std::string message = error_of(mink::read_mesh_points(missing));
  EXPECT_EQ(message, missing + ": cannot open: No such file or directory");

  const std::string dir = ::testing::TempDir() + "/mink_mesh_test/a_directory.stl";
  std::filesystem::create_directories(dir);
  message = error_of(mink::read_mesh_points(dir));
  EXPECT_EQ(message, dir + ": cannot read: Is a directory");
}

}  // namespace
