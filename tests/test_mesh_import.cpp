// Meshes read exactly (OBJ, OFF), split into fans, turned into scenes; every
// malformed file is rejected with its line; the rotation about a centroid is
// rigid and keeps the centroid.
#include <catch2/catch.hpp>

#include "kvd/scene/mesh_io.hpp"
#include "kvd/scene/scene_io.hpp"

using namespace kvd::scene;

namespace {

std::string source(const std::string& name) { return std::string(KVD_SOURCE_DIR) + "/data/meshes/" + name; }

// The message of the rejection, or "" when the mesh reads.
std::string rejection(const std::string& text, const std::string& name) {
  try {
    read_mesh(text, name);
    return "";
  } catch (const Scene_error& e) {
    return e.what();
  }
}

}  // namespace

TEST_CASE("mesh import: the bundled meshes read exactly, quads split into fans", "[mesh]") {
  const auto cubes = read_mesh(read_input(source("two-cubes.obj")), "two-cubes.obj");
  REQUIRE(cubes.size() == 2);
  CHECK(cubes[0].name == "left");
  CHECK(cubes[1].name == "right");
  for (const auto& o : cubes) {
    CHECK(o.vertices.size() == 8);
    CHECK(o.triangles.size() == 12);
  }
  // Negative indices count back from the last vertex read: the right cube's first corner is v9.
  CHECK(cubes[1].vertices[0] == QPoint{{Q(3, 2), Q(1, 4), Q(1, 4), Q(1)}});
  const auto pyramid = read_mesh(read_input(source("pyramid.ply")), "pyramid.ply");
  REQUIRE(pyramid.size() == 1);
  CHECK(pyramid[0].vertices.size() == 5);
  CHECK(pyramid[0].triangles.size() == 6);  // the quad base split in two
  CHECK(pyramid[0].vertices[4][2] == Q(5, 4));
  const auto octahedron = read_mesh(read_input(source("octahedron.off")), "octahedron.off");
  REQUIRE(octahedron.size() == 1);
  CHECK(octahedron[0].vertices.size() == 6);
  CHECK(octahedron[0].triangles.size() == 8);
  CHECK(octahedron[0].vertices[0][0] == Q(3, 2));  // "1.5", exactly
  // As a scene: the loader's checks pass, and writing and reading gives it back.
  const Scene s = mesh_scene(cubes, "two-cubes");
  CHECK(s.triangles.size() == 24);
  CHECK(s.edges.size() == 36);  // 12 cube edges and 6 face diagonals, twice
  CHECK(read_scene(write_scene(s), "two-cubes.json") == s);
}

TEST_CASE("mesh import: vertices no face uses are left out", "[mesh]") {
  const auto m = read_mesh("v 0 0 0\nv 9 9 9\nv 1 0 0\nv 0 1 0\nf 1 3 4\n", "a.obj");
  REQUIRE(m.size() == 1);
  CHECK(m[0].vertices.size() == 3);
  CHECK(m[0].triangles[0] == std::array<std::size_t, 3>{0, 1, 2});
}

TEST_CASE("mesh import: malformed meshes are rejected with their line", "[mesh]") {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  CHECK(rejection(tri + "f 1 2 3\n", "a.obj") == "");
  CHECK(rejection(tri + "f 1 2 3/1/1\nvt 0 0\nvn 0 0 1\ns off\nusemtl x\n", "a.obj") == "");
  CHECK(rejection(tri + "f 1 2 4\n", "a.obj") == "a.obj: line 4: vertex index 4 out of range (3 vertices so far)");
  CHECK(rejection(tri + "f 1 2 0\n", "a.obj").find("line 4: vertex index 0 out of range") != std::string::npos);
  CHECK(rejection(tri + "f -4 1 2\n", "a.obj").find("line 4: vertex index -4") != std::string::npos);
  CHECK(rejection(tri + "f 1 2\n", "a.obj") == "a.obj: line 4: a face needs at least three corners");
  CHECK(rejection(tri + "f 1 2 1\n", "a.obj") == "a.obj: line 4: a face repeats a corner");
  CHECK(rejection("v 0 0 zero\n", "a.obj").find("a.obj: line 1: not a number") == 0);
  CHECK(rejection("v 0 0 1e99999\n", "a.obj").find("line 1: exponent") != std::string::npos);
  CHECK(rejection("v 0 0\n", "a.obj").find("line 1: a vertex is") != std::string::npos);
  CHECK(rejection("v 0 0 0 0\n", "a.obj").find("line 1: a vertex with w = 0") != std::string::npos);
  CHECK(rejection(tri + "l 1 2\n", "a.obj").find("line 4: 'l' elements are not triangles") != std::string::npos);
  CHECK(rejection(tri + "fx 1 2 3\n", "a.obj").find("line 4: unknown statement 'fx'") != std::string::npos);
  CHECK(rejection(tri, "a.obj").find("no faces") != std::string::npos);
  CHECK(rejection("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "a.off") == "");
  CHECK(rejection("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n", "a.off") == "");  // a colour
  CHECK(rejection("COFF\n3 1 0\n", "a.off") == "a.off: line 1: an OFF file starts with 'OFF'");
  CHECK(rejection("OFF\n3 1 0\n0 0 0\n1 0 0\n", "a.off") == "a.off: line 4: the file ends early");
  CHECK(rejection("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "a.off").find("line 6: vertex index 3 out of range") !=
        std::string::npos);
  CHECK(rejection("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\nextra\n", "a.off") ==
        "a.off: line 7: unexpected text after the last face");
  CHECK(rejection("OFF\nthree 1 0\n", "a.off").find("line 2: expected the number of vertices") != std::string::npos);
  CHECK(rejection(tri, "a.stl") == "a.stl: unknown mesh format (expected a .obj, .off or .ply file)");
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n";
  CHECK(rejection(head + points + "3 0 1 2\n", "a.ply") == "");
  CHECK(rejection("ply\nformat binary_little_endian 1.0\n", "a.ply").find("line 2: only ASCII PLY") != std::string::npos);
  CHECK(rejection(head + points + "3 0 1\n", "a.ply") == "a.ply: line 13: a face declares 3 corners and lists 2");
  CHECK(rejection(head + points + "3 0 1 5\n", "a.ply").find("line 13: vertex index 5 out of range") != std::string::npos);
  CHECK(rejection(head + "0 0\n", "a.ply") == "a.ply: line 10: a vertex has 3 values");
  CHECK(rejection(head + points, "a.ply") == "a.ply: line 12: the file ends early");
  CHECK(rejection(head + points + "3 0 1 2\n9\n", "a.ply") == "a.ply: line 14: unexpected text after the last element");
  CHECK(rejection("ply\nformat ascii 1.0\nelement vertex x\n", "a.ply").find("line 3: expected the number of elements") !=
        std::string::npos);
}

TEST_CASE("mesh import: the rotation about the centroid is rigid and keeps the centroid", "[mesh]") {
  Scene s = mesh_scene(read_mesh(read_input(source("tetrahedron.off")), "tetrahedron.off"), "t");
  s.objects[0].motion = rotation_about_centroid(s, 0, {Q(1), Q(2), Q(-2)});
  s.derive();
  const auto squared = [](const QPoint& a, const QPoint& b) {
    Q d = 0;
    for (int i = 0; i < 3; ++i) d += (a[i] / a[3] - b[i] / b[3]) * (a[i] / a[3] - b[i] / b[3]);
    return d;
  };
  for (const Q& t : {Q(0), Q(1, 3), Q(1), Q(-5, 2), Q(7)}) {
    Q centroid[3] = {0, 0, 0};
    for (std::size_t v = 0; v < 4; ++v) {
      const QPoint p = s.position_at(v, t);
      for (int i = 0; i < 3; ++i) centroid[i] += p[i] / p[3] / 4;
      for (std::size_t w = 0; w < 4; ++w) CHECK(squared(p, s.position_at(w, t)) == squared(s.rest[v], s.rest[w]));
    }
    // The tetrahedron's centroid is the origin.
    for (const Q& c : centroid) CHECK(c == 0);
  }
  CHECK(s.max_motion_degree() == 2);
}
