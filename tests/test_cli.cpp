// The command-line contract: --help, --version, and exit status 2 on misuse.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>
#include <vector>

#include "kvd/version.hpp"

namespace {

struct Run {
  int status;
  std::string out;
};

// Runs kvd with `args`; `redirect` says where its output goes (by default
// stdout is captured, stderr dropped).
Run run(const std::string& args, const std::string& redirect = "2>/dev/null") {
  const std::string cmd = std::string(KVD_EXECUTABLE) + " " + args + " " + redirect;
  FILE* pipe = popen(cmd.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string out;
  std::array<char, 256> buf{};
  while (fgets(buf.data(), buf.size(), pipe)) out += buf.data();
  const int raw = pclose(pipe);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// An empty folder `name` under the build folder.
std::filesystem::path fresh_folder(const std::string& name) {
  const std::filesystem::path folder = std::filesystem::path(KVD_BINARY_DIR) / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

// How many entries the folder holds, checking that none is a temporary file
// an output left behind.
std::size_t entries_without_temporary(const std::filesystem::path& folder) {
  std::size_t entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(folder)) {
    INFO(e.path().string());
    CHECK(e.path().filename().string().find(".tmp") == std::string::npos);
    ++entries;
  }
  return entries;
}

}  // namespace

TEST_CASE("kvd --help prints usage and succeeds", "[cli]") {
  for (const char* flag : {"--help", "-h"}) {
    const Run r = run(flag);
    CHECK(r.status == 0);
    CHECK(r.out.find("usage: kvd") != std::string::npos);
  }
}

TEST_CASE("kvd --version prints the project version", "[cli]") {
  const Run r = run("--version");
  CHECK(r.status == 0);
  CHECK(r.out == std::string("kvd ") + kvd::version + "\n");
}

TEST_CASE("kvd rejects misuse with exit status 2", "[cli]") {
  CHECK(run("").status == 2);
  CHECK(run("no-such-command").status == 2);
  CHECK(run("--no-such-flag").status == 2);
}

TEST_CASE("kvd info prints exact counts of a bundled scene", "[cli][info]") {
  const std::string scene = std::string(KVD_SOURCE_DIR) + "/data/boxes.json";
  const Run r = run("info " + scene + " --json");
  CHECK(r.status == 0);
  // Two boxes: 8 vertices, 12 triangles, 12 + 6 edges each; one box moves linearly.
  CHECK(r.out.find("\"objects\": 2, \"vertices\": 16, \"edges\": 36, \"triangles\": 24, "
                   "\"moving_triangles\": 12, \"max_motion_degree\": 1}") != std::string::npos);
  const Run text = run("info " + scene);
  CHECK(text.status == 0);
  CHECK(text.out.find("triangles:         24\n") != std::string::npos);
  CHECK(run("info --help").out.find("usage: kvd info") != std::string::npos);
}

TEST_CASE("kvd info exits with status 2 on bad scenes and bad usage", "[cli][info]") {
  CHECK(run("info").status == 2);
  CHECK(run("info /no/such/file.json").status == 2);
  CHECK(run(std::string("info ") + KVD_SOURCE_DIR).status == 2);  // a directory
  CHECK(run("info - < /dev/null").status == 2);                      // empty input
  CHECK(run(std::string("info ") + KVD_SOURCE_DIR + "/data/boxes.json --seed -3").status == 2);
  CHECK(run(std::string("info ") + KVD_SOURCE_DIR + "/data/boxes.json --frobnicate").status == 2);
  CHECK(run(std::string("info ") + KVD_SOURCE_DIR + "/README.md").status == 2);  // not JSON
}

TEST_CASE("kvd order and kvd render describe and paint every fragment", "[cli][order][render]") {
  const std::string scene = std::string(KVD_SOURCE_DIR) + "/data/single-triangle.json";
  // The single triangle has two T-fragments (see test_build.cpp), listed
  // with exact coordinates.
  const Run order = run("order " + scene + " --view 1,1,10 --json");
  CHECK(order.status == 0);
  CHECK(order.out.rfind("{\"fragments\": [{\"triangle\": 0, \"vertices\": [[", 0) == 0);
  std::size_t fragments = 0;
  for (std::size_t at = order.out.find("\"triangle\""); at != std::string::npos; at = order.out.find("\"triangle\"", at + 1))
    ++fragments;
  CHECK(fragments == 2);
  CHECK(order.out.find("[\"1/3\", \"1\", \"1/3\"]") != std::string::npos);  // the thread vertex X, exactly
  const Run svg = run("render " + scene + " --view 1,1,10 --cells");
  CHECK(svg.status == 0);
  std::size_t polygons = 0;
  for (std::size_t at = svg.out.find("<polygon"); at != std::string::npos; at = svg.out.find("<polygon", at + 1)) ++polygons;
  CHECK(polygons == 2);
  CHECK(svg.out.find("#d62728") != std::string::npos);  // the P-cut side is drawn red
  CHECK(run("order " + scene).status == 2);             // no --view
  CHECK(run("order " + scene + " --view 1,2").status == 2);
  CHECK(run("render " + scene + " --view 1,1,10 --out picture.jpg").status == 2);
  // PNG through cairo: the file starts with the PNG signature.
  const std::string png = std::string(KVD_BINARY_DIR) + "/single-triangle.png";
  CHECK(run("render " + scene + " --view 1,1,10 --cells --size 64 --out " + png).status == 0);
  std::FILE* f = std::fopen(png.c_str(), "rb");
  REQUIRE(f != nullptr);
  unsigned char magic[8] = {};
  CHECK(std::fread(magic, 1, 8, f) == 8);
  std::fclose(f);
  CHECK(std::string(reinterpret_cast<char*>(magic), 8) == "\x89PNG\r\n\x1a\n");
  CHECK(run("build " + scene + " --kernel mpfr:x").status == 2);
  CHECK(run("build " + scene + " --time 1/0").status == 2);
}

TEST_CASE("kvd simulate reports exact event times and validates", "[cli][simulate]") {
  const Run r = run(std::string("simulate ") + KVD_SOURCE_DIR + "/data/two-triangles.json --json");
  CHECK(r.status == 0);
  CHECK(r.out.find("{\"time\": \"2\", \"approx\": \"2\", \"failing\": 1") != std::string::npos);
  // Three batches at 2, 3, 4 (see test_simulation.cpp); "events" counts the
  // certificate failures in them, so it is the sum of the batches' "failing".
  long failing = 0;
  for (std::size_t at = r.out.find("\"failing\": "); at != std::string::npos; at = r.out.find("\"failing\": ", at + 1))
    failing += std::stol(r.out.substr(at + 11));
  CHECK(r.out.find("\"events\": " + std::to_string(failing) + ",") != std::string::npos);
  // No failure after the last batch (t = 4): the run has certified the tree up to the span's end.
  CHECK(r.out.find("\"collisions\": 0, \"stopped\": \"exhausted\", \"validation\": \"every\", \"validations\": 3, "
                   "\"validation_failures\": 0") != std::string::npos);
  CHECK(r.out.find("\"time_reached_exact\": \"10\"") != std::string::npos);
  CHECK(run(std::string("simulate ") + KVD_SOURCE_DIR + "/data/two-triangles.json --validate sometimes").status == 2);
  // The trace: one JSON line per failure; the first is the mover's vertex v4
  // = (1,0,1) crossing the E-plane of the floor edge e1 from (4,-4) to (0,4).
  const std::string trace = std::string(KVD_BINARY_DIR) + "/two-triangles.jsonl";
  CHECK(run(std::string("simulate ") + KVD_SOURCE_DIR + "/data/two-triangles.json --trace " + trace).status == 0);
  std::FILE* f = std::fopen(trace.c_str(), "r");
  REQUIRE(f != nullptr);
  std::array<char, 512> line{};
  REQUIRE(std::fgets(line.data(), line.size(), f) != nullptr);
  std::fclose(f);
  CHECK(std::string(line.data()) ==
        "{\"batch\": 0, \"time\": \"2\", \"interval\": [\"2\", \"2\"], \"approx\": \"2\", "
        "\"certificate\": \"VE\", \"nodes\": \"SV(v4) E(1)\"}\n");
  // Both certificate sets and both queues give the same three batches.
  for (const char* opts : {" --certificates full --queue heap", " --queue heap", " --certificates full"}) {
    const Run other = run(std::string("simulate ") + KVD_SOURCE_DIR + "/data/two-triangles.json --json" + opts);
    CHECK(other.status == 0);
    CHECK(other.out.find("\"batches\": 3,") != std::string::npos);
    CHECK(other.out.find("\"time_reached_exact\": \"10\"") != std::string::npos);
  }
  CHECK(run(std::string("simulate ") + KVD_SOURCE_DIR + "/data/two-triangles.json --certificates some").status == 2);
  CHECK(run(std::string("simulate ") + KVD_SOURCE_DIR + "/data/two-triangles.json --queue list").status == 2);
  // --epsilon belongs to the floating-point kernels, and must be positive.
  CHECK(run(std::string("simulate ") + KVD_SOURCE_DIR + "/data/two-triangles.json --epsilon 1/1000").status == 2);
  CHECK(run(std::string("simulate ") + KVD_SOURCE_DIR + "/data/two-triangles.json --kernel double --epsilon 0").status == 2);
  CHECK(run(std::string("simulate ") + KVD_SOURCE_DIR + "/data/two-triangles.json --kernel double --epsilon 1/1000").status == 0);
  CHECK(run("simulate").status == 2);
  CHECK(run(std::string("simulate ") + KVD_SOURCE_DIR + "/data/two-triangles.json --events x").status == 2);
}

TEST_CASE("kvd certify writes the file whole, or not at all on bad input", "[cli][certify]") {
  const std::string scene = std::string(KVD_SOURCE_DIR) + "/data/two-triangles.json";
  const std::string out = std::string(KVD_BINARY_DIR) + "/two-triangles.cert.json";
  std::remove(out.c_str());
  CHECK(run("certify --help").out.find("usage: kvd certify") != std::string::npos);
  CHECK(run("certify " + scene).status == 2);                                  // no --out
  CHECK(run("certify " + scene + " --out " + out + " --events x").status == 2);
  CHECK(run("certify " + scene + " --out " + out + " --json").status == 2);     // not an option of certify
  CHECK(run("certify no-such-scene.json --out " + out).status == 2);
  CHECK(!std::ifstream(out).good());  // nothing written by the refused runs
  const Run r = run("certify " + scene + " --out " + out);
  CHECK(r.status == 0);
  CHECK(r.out.find("8 events in 3 batches") != std::string::npos);
  std::ifstream f(out);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  CHECK(text.rfind("{\n\"format\": \"kvd-event-order/2\"", 0) == 0);
  CHECK(text.find("\"motion_changes\": []\n}\n") != std::string::npos);
  // Through collisions: the four contacts of collisions.json become motion
  // changes; with --collisions stop the run ends at the first.
  const std::string collisions = std::string(KVD_SOURCE_DIR) + "/data/collisions.json";
  const Run reversed = run("certify " + collisions + " --events 200 --out " + out);
  CHECK(reversed.status == 0);
  CHECK(reversed.out.find("4 motion changes") != std::string::npos);
  const Run stopped = run("certify " + collisions + " --collisions stop --out " + out);
  CHECK(stopped.status == 0);
  CHECK(stopped.out.find("0 motion changes") != std::string::npos);
  CHECK(stopped.out.find("stopped by collision") != std::string::npos);
  CHECK(run("certify " + collisions + " --collisions bounce --out " + out).status == 2);
}

TEST_CASE("kvd diff compares kernels event by event; divergence exits 0, bad input 2", "[cli][diff]") {
  const std::string data = std::string(KVD_SOURCE_DIR) + "/data/";
  CHECK(run("diff --help").out.find("usage: kvd diff") != std::string::npos);
  CHECK(run("diff " + data + "two-triangles.json").status == 2);  // no --kernel
  CHECK(run("diff " + data + "two-triangles.json --kernel quad").status == 2);
  CHECK(run("diff " + data + "two-triangles.json --kernel mpfr:1").status == 2);
  CHECK(run("diff " + data + "two-triangles.json --kernel double --events x").status == 2);
  CHECK(run("diff no-such-scene.json --kernel double").status == 2);

  const Run same = run("diff " + data + "two-triangles.json --kernel double --json");
  REQUIRE(same.status == 0);
  const auto j = nlohmann::json::parse(same.out);
  CHECK(j["events_compared"] == 8);
  CHECK(j["events"].size() == 8);
  CHECK(j["first_divergence_event"].is_null());
  for (const char* field : {"order_mismatches", "missed_events", "spurious_events", "structure_mismatches"})
    CHECK(j[field] == 0);
  for (const char* field : {"max_time_error", "max_relative_time_error", "seconds_exact", "seconds_inexact"})
    CHECK(j[field].is_number());
  CHECK(j["events"][0]["in_order"] == true);
  CHECK(j["events"][0]["structure_equal"] == true);

  // Failures 1e-31 apart: double sees them at one time, so the trees after differ.
  const Run stiff = run("diff " + data + "stiff/close-events.json --kernel double --json");
  REQUIRE(stiff.status == 0);
  const auto k = nlohmann::json::parse(stiff.out);
  CHECK(k["first_divergence_event"] == 0);
  CHECK(k["structure_mismatches"].get<int>() > 0);
}

TEST_CASE("kvd bench accuracy writes its table, or nothing on bad input", "[cli][bench]") {
  const std::string out = std::string(KVD_BINARY_DIR) + "/bench-accuracy";
  const std::string common = " --events 5 --scenes two-triangles,stiff/close-events --data " +
                             std::string(KVD_SOURCE_DIR) + "/data --out " + out;
  std::remove((out + "/accuracy.csv").c_str());
  CHECK(run("bench").status == 2);
  CHECK(run("bench no-such-suite").status == 2);
  CHECK(run("bench --help").status == 0);
  CHECK(run("bench accuracy --help").out.find("usage: kvd bench accuracy") != std::string::npos);
  CHECK(run("bench accuracy" + common + " --kernels double,quad").status == 2);
  CHECK(run("bench accuracy --events 5 --scenes no-such-scene --out " + out).status == 2);
  CHECK(!std::ifstream(out + "/accuracy.csv").good());
  const Run r = run("bench accuracy" + common + " --kernels double,mpfr:53,exact");
  CHECK(r.status == 0);
  std::ifstream f(out + "/accuracy.csv");
  std::vector<std::string> lines;
  for (std::string line; std::getline(f, line);) lines.push_back(line);
  REQUIRE(lines.size() == 7);  // the header, two scenes by three kernels
  CHECK(lines[0].rfind("scene,kernel,events,", 0) == 0);
  CHECK(lines[1].rfind("two-triangles,double,8,", 0) == 0);
  CHECK(lines[6].rfind("stiff/close-events,exact,", 0) == 0);
}

TEST_CASE("kvd bench thesis writes the thesis's tables beside ours, or nothing on bad input", "[cli][bench]") {
  const std::string out = std::string(KVD_BINARY_DIR) + "/bench-thesis";
  const std::string data = " --data " + std::string(KVD_SOURCE_DIR) + "/data --out " + out;
  std::remove((out + "/thesis.md").c_str());
  CHECK(run("bench thesis --help").out.find("usage: kvd bench thesis") != std::string::npos);
  CHECK(run("bench thesis --sizes 0" + data).status == 2);
  CHECK(run("bench thesis --sizes 30" + data).status == 2);  // no scene of 30 triangles
  CHECK(run("bench thesis --sizes 25 --kernels exact,quad" + data).status == 2);
  CHECK(!std::ifstream(out + "/thesis.md").good());
  const Run r = run("bench thesis --sizes 25 --events 10" + data);
  REQUIRE(r.status == 0);
  std::ifstream f(out + "/thesis.md");
  const std::string md((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  // Figure 8.4 at 25 triangles: one P-node per vertex, in both.
  CHECK(md.find("| P-nodes | 75 / 75 |") != std::string::npos);
  // A static scene makes no certificate.
  CHECK(md.find("| uniform-scale 25 | 0 / ") != std::string::npos);
  CHECK(std::ifstream(out + "/thesis.csv").good());
}

TEST_CASE("kvd bench update compares the local update with the rebuild over N, or writes nothing on bad input",
          "[cli][bench]") {
  const std::string out = std::string(KVD_BINARY_DIR) + "/bench-update";
  const std::string to = " --out " + out;
  std::remove((out + "/update.md").c_str());
  CHECK(run("bench update --help").out.find("usage: kvd bench update") != std::string::npos);
  CHECK(run("bench update --sizes 0" + to).status == 2);
  CHECK(run("bench update --sizes 20,x" + to).status == 2);
  CHECK(run("bench update --events x" + to).status == 2);
  CHECK(!std::ifstream(out + "/update.md").good());
  const Run r = run("bench update --sizes 20,10 --events 20 --rebuild-up-to 10 --upkeep-all-up-to 0" + to);
  REQUIRE(r.status == 0);
  std::ifstream f(out + "/update.md");
  const std::string md((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  // The sizes in increasing order, the rebuild only up to 10 triangles, no
  // run with --upkeep all, and the exact runs of each size in one tree.
  CHECK(md.find("| 10 | ") < md.find("| 20 | "));
  CHECK(md.find("**no**") == std::string::npos);
  std::ifstream c(out + "/update.csv");
  const std::string csv((std::istreambuf_iterator<char>(c)), std::istreambuf_iterator<char>());
  CHECK(csv.find("10,\"rebuild\"") != std::string::npos);
  CHECK(csv.find("20,\"rebuild\"") == std::string::npos);
  CHECK(csv.find("20,\"local, double\"") != std::string::npos);
  CHECK(csv.find("upkeep all") == std::string::npos);
}

TEST_CASE("kvd bench cost compares exact with double and counts the filter's stages, or writes nothing on bad input",
          "[cli][bench]") {
  const std::string out = std::string(KVD_BINARY_DIR) + "/bench-cost";
  const std::string to = " --out " + out;
  std::remove((out + "/cost.md").c_str());
  std::remove((out + "/cost.csv").c_str());
  CHECK(run("bench cost --help").out.find("usage: kvd bench cost") != std::string::npos);
  CHECK(run("bench cost --sizes 0" + to).status == 2);
  CHECK(run("bench cost --repeats 0" + to).status == 2);
  CHECK(run("bench cost --repeats x" + to).status == 2);
  CHECK(!std::ifstream(out + "/cost.md").good());
  const Run r = run("bench cost --sizes 20,10 --events 20 --repeats 1" + to);
  REQUIRE(r.status == 0);
  std::ifstream f(out + "/cost.md");
  const std::string md((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  CHECK(md.find("| 10 | ") < md.find("| 20 | "));
  // One row per size; the columns are named in the header.
  std::ifstream c(out + "/cost.csv");
  std::string header, line;
  std::getline(c, header);
  std::vector<std::string> names;
  for (std::stringstream hs(header); std::getline(hs, line, ',');) names.push_back(line);
  int rows = 0;
  while (std::getline(c, line)) {
    ++rows;
    std::map<std::string, std::string> v;
    std::stringstream ls(line);
    for (const std::string& n : names) std::getline(ls, v[n], ',');
    INFO(line);
    // Linear motions make certificate polynomials of degree 1 (proofs/degree-bounds.md).
    CHECK(std::stol(v["polynomials"]) > 0);
    CHECK(v["linear_polynomials"] == v["polynomials"]);
    CHECK(v["max_degree"] == "1");
    // The filter decides classifications of the build.
    CHECK(std::stol(v["build_classify_filter"]) > 0);
    CHECK(std::stol(v["events"]) >= 20);
    CHECK(v["double_failure"] == "\"\"");
  }
  CHECK(rows == 2);
}

namespace {

// Writes a scene (or any text) under the build folder; returns its path.
std::string scene_file(const std::string& name, const std::string& text) {
  const std::string path = std::string(KVD_BINARY_DIR) + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

const std::string floor_tri = R"({"vertices": [["-1","0","-1"],["1","0","-1"],["0","0","1"]], "triangles": [[0,1,2]]})";

}  // namespace

TEST_CASE("scenes that crashed or hung end with a message and status 2", "[cli][trust]") {
  // Two triangles crossing at the start: Build_error reached std::terminate (exit 134).
  const std::string crossing = scene_file("crossing.json", R"({"format": "kvd-scene/1", "objects": [)" + floor_tri +
      R"(, {"vertices": [["0","-1","0"],["0","1","0"],["0","0","2"]], "triangles": [[0,1,2]],
            "motion": {"translation": [[0, 1], 0, 0]}}]})");
  CHECK(run("simulate " + crossing + " --allow-intersecting").status == 2);
  CHECK(run("certify " + crossing + " --allow-intersecting --out " + std::string(KVD_BINARY_DIR) + "/crossing.cert").status == 2);
  CHECK(run("diff " + crossing + " --allow-intersecting --kernel double").status == 2);
  CHECK(run("build " + crossing + " --allow-intersecting").status == 2);
  // W = 1 - t: order and render at t = 1 died of SIGFPE (exit 136).
  const std::string w_zero = scene_file("w-zero.json", R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 2}, "objects": [)" +
      floor_tri + R"(, {"vertices": [[0,5,0],[1,5,0],[0,5,1]], "triangles": [[0,1,2]],
            "motion": {"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,[1,-1]]]}}]})");
  for (const char* command : {"info", "simulate", "order --view 1,2,30 --time 1", "render --view 1,2,30 --time 1"})
    CHECK(run(std::string(command) + " " + w_zero).status == 2);
  // -1e400 is infinite in double: the double run hung.
  const std::string huge = scene_file("huge.json", R"({"format": "kvd-scene/1", "objects": [)" + floor_tri +
      R"(, {"vertices": [["-1e400","5","0"],[1,5,0],[0,5,1]], "triangles": [[0,1,2]], "motion": {"translation": [0, [0, 1], 0]}}]})");
  CHECK(run("simulate " + huge + " --kernel double").status == 2);
  CHECK(run("build " + huge + " --kernel double").status == 2);
  CHECK(run("diff " + huge + " --kernel double").status == 2);
  CHECK(run("build " + huge + " --kernel mpfr:53").status == 0);
  CHECK(run("build " + huge).status == 0);
}

TEST_CASE("kvd order and kvd render at an instant where cuts degenerate", "[cli][order][render][trust]") {
  // The mover's vertex (0, 0, 1) is on the line x ∨ z at the start: its
  // P-cut and the corners on it vanish there, and order and render divided
  // by their W of zero (SIGFPE, exit 136). The tree at 0 holds just after 0;
  // its corners at 0 are their limits from after 0.
  const std::string objects = R"(, "objects": [
      {"name": "floor", "vertices": [["-4","-4","0"], ["4","-4","0"], ["0","4","0"]], "triangles": [[0,1,2]]},
      {"name": "mover", "vertices": [["0","0","1"], ["1","0","1"], ["0","1","2"]], "triangles": [[0,1,2]],
       "motion": {"translation": [["0","1/2"], "0", "0"]}}]})";
  const std::string head = R"({"format": "kvd-scene/1", "time": {"start": "0", "end": "10"}, "decomposition": )";
  const std::string on_axis =
      scene_file("on-axis.json", head + R"({"x": ["0", "0", "0", "1"], "z": ["0", "0", "1", "0"]})" + objects);
  const Run order = run("order " + on_axis + " --view 10,10,10");
  CHECK(order.status == 0);
  CHECK(order.out.find("triangle 1: (1/2 1/2 3/2) (0 1 2) (0 0 1)\n") != std::string::npos);
  CHECK(run("order " + on_axis + " --view 10,10,10 --cull").status == 0);
  CHECK(run("render " + on_axis + " --view 10,10,10").out.find("<polygon") != std::string::npos);
  // x meets z, or vanishes, at t = 1: every P-cut degenerates there.
  for (const char* x : {R"([["1","-1"], "0", ["0","1"], "0"])", R"([["1","-1"], "0", "0", "0"])"}) {
    INFO(x);
    const std::string at_one = scene_file("x-degenerate.json", head + R"({"x": )" + x + "}" + objects);
    for (const char* command : {"order --view 10,10,10 --time 1", "render --view 10,10,10 --time 1", "build --time 1"})
      CHECK(run(std::string(command) + " " + at_one).status == 0);
    CHECK(run("order " + at_one + " --view 10,10,10 --time 1").out.find("triangle 1: (1/2 0 1) (3/2 0 1)") !=
          std::string::npos);
  }
}

TEST_CASE("a floating-point kernel that rounds valid triangles into crossing fails the run, not the scene", "[cli][trust]") {
  // At 8 bits the first build of two generated boxes finds triangles
  // crossing that the exact kernel keeps apart: reported as bad input (2).
  const std::string boxes = std::string(KVD_BINARY_DIR) + "/rounded-boxes.json";
  REQUIRE(run("generate boxes --boxes 2 --seed 1 -o " + boxes).status == 0);
  for (const std::string command : {"simulate", "build", "diff"}) {
    INFO(command);
    const Run r = run(command + " " + boxes + " --kernel mpfr:8", "2>&1 >/dev/null");
    CHECK(r.status == 1);
    CHECK(r.out.find("failed by rounding") != std::string::npos);
    CHECK(r.out.find(boxes) != std::string::npos);
  }
  CHECK(run("simulate " + boxes).status == 0);
  // Triangles that do cross stay bad input in every kernel.
  const std::string crossing = scene_file("crossing-rounded.json", R"({"format": "kvd-scene/1", "objects": [)" + floor_tri +
      R"(, {"vertices": [["0","-1","0"],["0","1","0"],["0","0","2"]], "triangles": [[0,1,2]]}]})");
  CHECK(run("build " + crossing + " --allow-intersecting --kernel double").status == 2);
  CHECK(run("simulate " + crossing + " --allow-intersecting --kernel mpfr:8").status == 2);
}

TEST_CASE("times outside the scene's span are refused", "[cli][trust]") {
  const std::string scene = std::string(KVD_SOURCE_DIR) + "/data/two-triangles.json";  // span [0, 10]
  CHECK(run("build " + scene + " --time 11").status == 2);
  CHECK(run("build " + scene + " --time -1").status == 2);
  CHECK(run("build " + scene + " --time 10").status == 0);
  CHECK(run("order " + scene + " --view 0,0,50 --time 20").status == 2);
  CHECK(run("simulate " + scene + " --until 10.5").status == 2);
  CHECK(run("simulate " + scene + " --until -1").status == 2);
  CHECK(run("certify " + scene + " --until 11 --out " + std::string(KVD_BINARY_DIR) + "/span.cert").status == 2);
}

TEST_CASE("numbers that double cannot hold are refused where double is used", "[cli][trust]") {
  // An epsilon of 1e400 was infinity in the double kernel (the run stuck at
  // its start with no message), and a view of 1e400 drew NaN.
  const std::string scene = std::string(KVD_SOURCE_DIR) + "/data/segments/two-crossing.json";
  CHECK(run("simulate " + scene + " --kernel double --epsilon 1e400").status == 2);
  CHECK(run("simulate " + scene + " --kernel double --epsilon 1e-400").status == 2);
  CHECK(run("simulate " + scene + " --kernel mpfr:53 --epsilon 1e400").status != 2);  // MPFR holds it
  CHECK(run("simulate " + scene + " --kernel double --epsilon 1e-12").status == 0);
  const std::string triangles = std::string(KVD_SOURCE_DIR) + "/data/two-triangles.json";
  CHECK(run("render " + triangles + " --view 1e400,0,0").status == 2);
  CHECK(run("render " + triangles + " --view 0,0,-1e400").status == 2);
  CHECK(run("render " + triangles + " --view 10,10,10").status == 0);
  // A scene number beyond double's range was drawn as NaN ("-nan,nan" in
  // every polygon) by render, animate and the viewer page, with status 0.
  // They refuse it, naming the file and the number's place, and write nothing.
  const std::filesystem::path folder = fresh_folder("not-drawable");
  const std::string huge_triangles = (folder / "huge.json").string(), huge_segments = (folder / "huge-segments.json").string();
  std::ofstream(huge_triangles) << R"({"format": "kvd-scene/1", "objects": [)" + floor_tri +
                                       R"(, {"vertices": [["-1e400","5","0"],[1,5,0],[0,5,1]], "triangles": [[0,1,2]]}]})";
  std::ofstream(huge_segments) << R"({"format": "kvd-segments/1", "segments": [{"endpoints": [["0","0"],["4","0"]]},
      {"endpoints": [["3","4"],["1e400","1"]], "motion": {"translation": ["0", ["0", "-1"]]}}]})";
  for (const auto& [scene, place] : {std::pair{huge_triangles, "/objects/1/vertices/0/0"}, std::pair{huge_segments, "/segments/1"}})
    for (const std::string& command : {"render --view 30,-40,25 --out " + (folder / "p.svg").string(),
                                      "animate --view 30,-40,25 --out " + (folder / "a.svg").string(),
                                      "view --out " + (folder / "v.html").string()}) {
      const bool segments = scene == huge_segments;
      const std::string args = segments ? command.substr(0, command.find(' ')) + command.substr(command.find(" --out"))
                                        : command;
      INFO(args << " " << scene);
      const Run r = run(args.substr(0, args.find(' ')) + " " + scene + args.substr(args.find(' ')), "2>&1");
      CHECK(r.status == 2);
      CHECK(r.out.find(scene + ": " + place + ":") != std::string::npos);
      CHECK(r.out.find("in double, in which pictures are drawn") != std::string::npos);
    }
  CHECK(entries_without_temporary(folder) == 2);  // the two scenes
  CHECK(run("build " + huge_triangles).status == 0);  // the exact build holds it
}

TEST_CASE("vertices of no triangle cost nothing and change no tree", "[cli][trust]") {
  const std::string without = scene_file("used.json", R"({"format": "kvd-scene/1", "objects": [)" + floor_tri +
      R"(, {"vertices": [[0,5,0],[1,5,0],[0,5,1]], "triangles": [[0,1,2]], "motion": {"translation": [0, [0, -1], 0]}}]})");
  std::string extra;
  for (int i = 0; i < 2000; ++i) extra += ",[" + std::to_string(i) + ",7,7]";
  const std::string with = scene_file("unused.json", R"({"format": "kvd-scene/1", "objects": [)" + floor_tri +
      R"(, {"vertices": [[0,5,0],[1,5,0],[0,5,1])" + extra + R"(], "triangles": [[0,1,2]], "motion": {"translation": [0, [0, -1], 0]}}]})");
  const auto a = nlohmann::json::parse(run("build " + without + " --json").out);
  const auto b = nlohmann::json::parse(run("build " + with + " --json").out);
  CHECK(b["vertices"] == 2006);
  CHECK(a["p_nodes"] == 6);
  CHECK(b["p_nodes"] == 6);
  CHECK(a["structure_hash"] == b["structure_hash"]);
}

TEST_CASE("outputs are written whole or not at all, and leave no temporary file", "[cli][trust]") {
  const std::filesystem::path folder = fresh_folder("atomic-out");
  const std::string scene = std::string(KVD_SOURCE_DIR) + "/data/two-triangles.json";
  const std::filesystem::path trace = folder / "run.jsonl";
  std::ofstream(trace) << "old contents\n";
  CHECK(run("simulate " + scene + " --events 5 --trace " + trace.string()).status == 0);
  CHECK(file_text(trace).rfind("{\"batch\": 0", 0) == 0);
  // A folder that does not exist: status 2, the old file untouched elsewhere, nothing left behind.
  CHECK(run("generate boxes -o " + (folder / "missing" / "x.json").string()).status == 2);
  CHECK(run("simulate " + scene + " --events 5 --trace " + (folder / "missing" / "t.jsonl").string()).status == 2);
  CHECK(entries_without_temporary(folder) == 1);
}

TEST_CASE("an output that is a device, a FIFO or a link is written through, not replaced", "[cli][trust]") {
  // The temporary file was renamed over the target: over /dev/null, as root,
  // it replaced the device node by a regular file.
  namespace fs = std::filesystem;
  const fs::path folder = fresh_folder("through-out");
  const fs::path fifo = folder / "pipe";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  // Held open for reading first, without blocking, so that the tool's open
  // for writing does not wait; the scene fits in the pipe's buffer.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  REQUIRE(reader >= 0);
  CHECK(run("generate segments-random --n 5 -o " + fifo.string()).status == 0);
  std::string got;
  std::array<char, 4096> buf{};
  for (ssize_t n; (n = ::read(reader, buf.data(), buf.size())) > 0;) got.append(buf.data(), static_cast<std::size_t>(n));
  ::close(reader);
  CHECK(got.find("\"kvd-segments/1\"") != std::string::npos);
  CHECK(fs::is_fifo(fifo));
  const fs::path file = folder / "file.json", link = folder / "link.json";
  std::ofstream(file) << "old contents\n";
  fs::create_symlink(file.filename(), link);
  CHECK(run("generate segments-random --n 5 -o " + link.string()).status == 0);
  CHECK(fs::is_symlink(link));
  CHECK(file_text(file).find("\"kvd-segments/1\"") != std::string::npos);
  // A folder is no file: status 2.
  CHECK(run("generate segments-random --n 5 -o " + folder.string()).status == 2);
  CHECK(entries_without_temporary(folder) == 3);
}

TEST_CASE("output lost on standard output is status 2", "[cli][trust]") {
  // /dev/full refuses every write; the status was 0 and the output gone.
  const std::string scene = std::string(KVD_SOURCE_DIR) + "/data/two-triangles.json";
  for (const std::string& args : std::vector<std::string>{"generate segments-random --n 5", "info " + scene, "--help"}) {
    INFO(args);
    CHECK(run(args, "> /dev/full 2>/dev/null").status == 2);
    CHECK(run(args, "> /dev/null 2>/dev/null").status == 0);
  }
}

TEST_CASE("every command in kvd's table answers --help", "[cli]") {
  const std::string usage = run("--help").out;
  const std::size_t from = usage.find("commands:\n"), to = usage.find("\noptions:");
  REQUIRE(from != std::string::npos);
  REQUIRE(to != std::string::npos);
  std::istringstream lines(usage.substr(from + 10, to - from - 10));
  std::size_t commands = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty()) continue;
    const std::string name = line.substr(2, line.find(' ', 2) - 2);
    INFO(name);
    const Run help = run(name + " --help");
    CHECK(help.status == 0);
    CHECK(help.out.rfind("usage: kvd " + name, 0) == 0);
    ++commands;
  }
  CHECK(commands >= 9);
}

TEST_CASE("kvd import: a mesh becomes a scene that info and build agree on", "[cli][import]") {
  const std::string meshes = std::string(KVD_SOURCE_DIR) + "/data/meshes/";
  const std::string out = std::string(KVD_BINARY_DIR) + "/two-cubes.json";
  CHECK(run("import " + meshes + "two-cubes.obj --translate right=-1/4,0,0 --rotate left=0,0,1/4 --end 2 -o " + out).status == 0);
  const auto info = nlohmann::json::parse(run("info " + out + " --json").out);
  CHECK(info["objects"] == 2);
  CHECK(info["vertices"] == 16);
  CHECK(info["triangles"] == 24);
  CHECK(info["moving_triangles"] == 24);
  CHECK(info["max_motion_degree"] == 2);
  const auto built = nlohmann::json::parse(run("build " + out + " --json").out);
  CHECK(built["triangles"] == 24);
  CHECK(built["p_nodes"] == 16);
  // Standard output, and a static mesh.
  const Run tetra = run("import " + meshes + "tetrahedron.off");
  CHECK(tetra.status == 0);
  CHECK(tetra.out.find("\"format\": \"kvd-scene/1\"") != std::string::npos);
  // Bad meshes, intersecting objects and bad usage: status 2, nothing written.
  const std::string bad = scene_file("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  const std::string crossing = scene_file("crossing.obj",
      "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 1 1 -1\nv 1 1 1\nv 3 3 0\no a\nf 1 2 3\no b\nf 4 5 6\n");
  const std::string never = std::string(KVD_BINARY_DIR) + "/never-written.json";
  std::filesystem::remove(never);
  CHECK(run("import " + bad + " -o " + never).status == 2);
  CHECK(run("import " + crossing + " -o " + never).status == 2);
  CHECK(run("import " + meshes + "two-cubes.obj --translate nobody=1,0,0 -o " + never).status == 2);
  CHECK(run("import " + meshes + "two-cubes.obj --translate 1,0,0 --rotate 0,0,1 -o " + never).status == 2);
  CHECK(run("import " + meshes + "missing.obj").status == 2);
  CHECK_FALSE(std::filesystem::exists(never));
}

TEST_CASE("kvd view and kvd animate refuse bad input with status 2 and write nothing", "[cli][view][animate]") {
  const std::string data = std::string(KVD_SOURCE_DIR) + "/data/";
  const std::string dir = std::string(KVD_BINARY_DIR) + "/";
  const std::string page = dir + "refused.html", film = dir + "refused.svg", trace = dir + "view-boxes.trace";
  std::remove(page.c_str());
  std::remove(film.c_str());
  CHECK(run("view " + data + "boxes.json").status == 2);                                  // no --out
  CHECK(run("view " + data + "boxes.json --out " + dir + "refused.svg").status == 2);     // not .html
  CHECK(run("view " + data + "no-such.json --out " + page).status == 2);
  CHECK(run("view " + data + "boxes.json --events x --out " + page).status == 2);
  REQUIRE(run("simulate " + data + "boxes.json --events 5 --trace " + trace).status == 0);
  CHECK(run("view " + trace + " --out " + page).status == 2);                             // a trace needs --scene
  CHECK(run("view " + trace + " --scene " + data + "two-triangles.json --out " + page).status == 2);  // not its run
  {  // a trace whose first event was altered
    std::ifstream in(trace);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find("\"certificate\": \"");
    REQUIRE(at != std::string::npos);
    text.insert(at + 16, "X");
    std::ofstream(dir + "view-altered.trace") << text;
  }
  CHECK(run("view " + dir + "view-altered.trace --scene " + data + "boxes.json --out " + page).status == 2);
  // A kvd diff report names its scene: --scene is refused, not ignored.
  const std::string report = dir + "view-boxes-diff.json";
  REQUIRE(run("diff " + data + "boxes.json --kernel double --json > " + report).status == 0);
  const Run given = run("view " + report + " --scene " + data + "boxes.json --out " + page, "2>&1");
  CHECK(given.status == 2);
  CHECK(given.out.find("--scene is for a trace") != std::string::npos);
  CHECK(!std::ifstream(page).good());
  CHECK(run("animate " + data + "boxes.json --view 1,2 --out " + film).status == 2);      // not a point
  CHECK(run("animate " + data + "boxes.json --view 1,2,3").status == 2);                  // no --out
  CHECK(run("animate " + data + "boxes.json --view 1,2,3 --out " + dir + "x.avi").status == 2);
  CHECK(run("animate " + data + "boxes.json --view 1,2,3 --fps 0 --out " + film).status == 2);
  CHECK(!std::ifstream(film).good());
}

TEST_CASE("kvd view refuses a trace or report with a field of the wrong type and names the file and the field",
          "[cli][view]") {
  // A null or a number where kvd view reads a string (or an object) ended in
  // "internal error" (a JSON type_error) and status 1.
  const std::string data = std::string(KVD_SOURCE_DIR) + "/data/";
  const std::string dir = std::string(KVD_BINARY_DIR) + "/";
  const std::string scene = data + "two-triangles.json", page = dir + "wrong-type.html";
  const std::string trace = dir + "wrong-type.trace", report = dir + "wrong-type-diff.json";
  std::remove(page.c_str());
  REQUIRE(run("simulate " + scene + " --trace " + trace).status == 0);
  std::ifstream in(trace);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const struct {
    const char *from, *to, *message;
  } lines[] = {{"\"time\": \"2\"", "\"time\": null", ": line 1: a trace line with a field of the wrong type: \"time\" is null"},
               {"\"certificate\": \"VE\"", "\"certificate\": 7", ": line 1: a trace line with a field of the wrong type: \"certificate\" is a number"},
               {"\"nodes\": \"SV(v4) E(1)\"", "\"nodes\": null", ": line 1: a trace line with a field of the wrong type: \"nodes\" is null"}};
  for (const auto& l : lines) {
    INFO(l.to);
    std::string altered = text;
    const auto at = altered.find(l.from);
    REQUIRE(at != std::string::npos);
    altered.replace(at, std::strlen(l.from), l.to);
    const std::string file = scene_file("wrong-type-altered.trace", altered);
    const Run r = run("view " + file + " --scene " + scene + " --out " + page, "2>&1 >/dev/null");
    CHECK(r.status == 2);
    CHECK(r.out.find("kvd view: " + file + l.message) != std::string::npos);
  }
  REQUIRE(run("diff " + scene + " --kernel double --json > " + report).status == 0);
  std::ifstream report_in(report);
  const nlohmann::json diff = nlohmann::json::parse(report_in);
  REQUIRE(diff["events"].size() > 2);
  const struct {
    const char* pointer;
    nlohmann::json value;
    const char* message;
  } fields[] = {{"/events/0/exact_time", nullptr, "/events/0/exact_time is null, not a string"},
                {"/events/1/certificate", 3, "/events/1/certificate is a number, not a string"},
                {"/events/2/nodes", nullptr, "/events/2/nodes is null, not a string"},
                {"/events/2/exact_time", 2.5, "/events/2/exact_time is a number, not a string"},
                {"/events/1", 5, "/events/1 is a number, not an object"},
                {"/kernel", nullptr, "/kernel is null, not a string"},
                {"/scene", 1, "/scene is a number, not a string"},
                {"/events", nlohmann::json::object(), "/events is an object, not an array"}};
  for (const auto& f : fields) {
    INFO(f.pointer);
    nlohmann::json altered = diff;
    altered[nlohmann::json::json_pointer(f.pointer)] = f.value;
    const std::string file = scene_file("wrong-type-diff-altered.json", altered.dump());
    const Run r = run("view " + file + " --out " + page, "2>&1 >/dev/null");
    CHECK(r.status == 2);
    CHECK(r.out.find("kvd view: " + file + ": a kvd diff report with a field of the wrong type: " + f.message) !=
          std::string::npos);
  }
  CHECK(!std::ifstream(page).good());
  // Unaltered, both are read (a build without the viewer page stops after).
  for (const std::string& args : {trace + " --scene " + scene, report}) {
    const Run r = run("view " + args + " --out " + page, "2>&1");
    CHECK((r.status == 0 || r.out.find("has no viewer page") != std::string::npos));
  }
}

TEST_CASE("kvd info tells segment scenes by their format and counts them exactly", "[cli][info][segments]") {
  const std::string dir = std::string(KVD_SOURCE_DIR) + "/data/segments/";
  const Run json = run("info " + dir + "two-crossing.json --json");
  CHECK(json.status == 0);
  CHECK(json.out.find("\"format\": \"kvd-segments/1\", \"name\": \"two-crossing\", \"segments\": 2, "
                      "\"moving_segments\": 0, \"max_motion_degree\": 0, \"crossings_at_start\": 1, "
                      "\"start\": \"0\", \"end\": \"10\"}") != std::string::npos);
  const Run text = run("info - < " + dir + "over-endpoint.json");
  CHECK(text.status == 0);
  CHECK(text.out.find("scene:             over-endpoint (-)\n") != std::string::npos);
  CHECK(text.out.find("segments:          2\nmoving segments:   1\nmax motion degree: 1\n") != std::string::npos);
  CHECK(text.out.find("crossings:         0 (at the start time)\ntime span:         [0, 7/2]\n") != std::string::npos);
  // A bad segment file: status 2, the message names the file and the place.
  const std::string bad = scene_file("bad-segments.json", R"({"format": "kvd-segments/1", "segments": [
      {"endpoints": [[0, 0], [1, 1]]}, {"endpoints": [[2, 2], [4, 4, 2]]}]})");
  CHECK(run("info " + bad).status == 2);
  const Run message = run("info " + bad, "2>&1 >/dev/null");
  CHECK(message.out.find(bad + ": /segments/1: the segment has zero length") != std::string::npos);
  CHECK(run("info " + bad + " --json", "2>&1 >/dev/null").out.find(bad + ": /segments/1: ") != std::string::npos);
  // A triangle scene's flag is refused, not ignored.
  const Run flag = run("info " + dir + "two-crossing.json --allow-intersecting", "2>&1");
  CHECK(flag.status == 2);
  CHECK(flag.out.find("--allow-intersecting: only for triangle scenes") != std::string::npos);
}

TEST_CASE("kvd generate writes segment scenes that kvd info reads back", "[cli][generate][segments]") {
  const std::string out = std::string(KVD_BINARY_DIR) + "/segments-random.json";
  std::remove(out.c_str());
  const std::string args = "generate segments-random --n 100 --length 0.1 --moving 50 --motion linear --seed 3";
  REQUIRE(run(args + " -o " + out).status == 0);
  const Run info = run("info " + out + " --json");
  CHECK(info.status == 0);
  CHECK(info.out.find("\"segments\": 100, \"moving_segments\": 50, \"max_motion_degree\": 1") != std::string::npos);
  // The same options give the same bytes, on stdout too.
  std::ifstream in(out);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(run(args).out == written);
  CHECK(run("generate segments-rotating --n 5").out.find("\"matrix\"") != std::string::npos);
  CHECK(run("generate segments-degenerate --n 9 --moving 0").status == 0);
  const std::string help = run("generate --help").out;
  for (const char* family : {"segments-random", "segments-rotating", "segments-degenerate"})
    CHECK(help.find(family) != std::string::npos);
  CHECK(run("generate segments-random --n 5 --moving 6").status == 2);
  CHECK(run("generate segments-random --moving 1/2").status == 2);
  CHECK(run("generate segments-random --motion spin").status == 2);
  CHECK(run("generate segments-rotating --motion linear").status == 2);
  CHECK(run("generate segments-random --length 2").status == 2);
  CHECK(run("generate segments-spiral").status == 2);
  // Each family refuses the options it does not read rather than ignore them.
  const Run triangles = run("generate segments-random --n 5 --triangles 5 --degree 2", "2>&1");
  CHECK(triangles.status == 2);
  CHECK(triangles.out.find("--triangles, --degree: not read by the family segments-random") != std::string::npos);
  const Run segments = run("generate uniform-density --triangles 5 --n 5 --end 2", "2>&1");
  CHECK(segments.status == 2);
  CHECK(segments.out.find("--n, --end: not read by the family uniform-density") != std::string::npos);
  for (const char* args : {"rotor --moving 1/2", "boxes --degree 3", "segments-degenerate --length 1/2"})
    CHECK(run(std::string("generate ") + args).status == 2);
  CHECK(run("generate spiral --n 5", "2>&1").out.find("unknown family 'spiral'") != std::string::npos);
}

TEST_CASE("kvd build and kvd simulate run the cylindrical BSP of a segment scene", "[cli][build][simulate][segments]") {
  const std::string dir = std::string(KVD_SOURCE_DIR) + "/data/segments/";
  // Two segments crossing once: four vertex cuts, an intersection cut above
  // and below the crossing, three fragments.
  const Run b = run("build " + dir + "two-crossing.json --json");
  REQUIRE(b.status == 0);
  CHECK(b.out.find("\"segments\": 2, \"crossings\": 1, \"vertex_cuts\": 4, \"intersection_cuts\": 2, \"edge_cuts\": 3, "
                   "\"nodes\": 19, \"leaves\": 10, \"height\": 7") != std::string::npos);
  CHECK(run("build " + dir + "two-crossing.json --tree").out ==
        "(V s0.0 . (V s0.1 (E s0 (V s1.1 (I s0xs1 . (E s1 . .)) .) (V s1.0 . (I s0xs1 (E s1 . .) .))) .))\n");
  // The needle turns through vertical at t = 1 (a flip): the tree changes,
  // the augmented tree (its two vertex cuts one ternary node) does not.
  const std::string flip = "build " + dir + "turning-vertical.json --time ";
  CHECK(run(flip + "1/2 --tree").out != run(flip + "3/2 --tree").out);
  CHECK(run(flip + "1/2 --augmented").out == "(T s0.0 s0.1 . (E s0 . (T s1.0 s1.1 . (E s1 . .) .)) .)\n");
  CHECK(run(flip + "3/2 --augmented").out == run(flip + "1/2 --augmented").out);
  CHECK(run(flip + "1/2 --augmented --tree").status == 2);  // one of them
  const Run boxes = run("build " + std::string(KVD_SOURCE_DIR) + "/data/boxes.json --augmented", "2>&1");
  CHECK(boxes.status == 2);
  CHECK(boxes.out.find("--augmented: only for kvd-segments/1 scenes") != std::string::npos);
  // The sinker passes over the floor's right endpoint at t = 3: one edge
  // event, validated against a fresh build; the same in double.
  for (const char* kernel : {"exact", "double"}) {
    const Run s = run("simulate " + dir + "over-endpoint.json --json --list --kernel " + kernel);
    REQUIRE(s.status == 0);
    CHECK(s.out.find("\"batches\": 1, \"failures\": 1") != std::string::npos);
    CHECK(s.out.find("\"failures_by_event\": {\"vertex\": 0, \"edge\": 1, \"intersection\": 0, \"flip\": 0}") !=
          std::string::npos);
    CHECK(s.out.find("\"validations\": 1, \"validation_failures\": 0") != std::string::npos);
  }
  CHECK(run("simulate " + dir + "over-endpoint.json --list").out.find("t = 3 (3): 1 failing, 1 edge, tree changed") !=
        std::string::npos);
  // The time reached, as for triangle scenes: the span's end (7/2) or
  // --until when no failure is left before it, else the last batch's.
  for (const char* set : {"kept", "paper"}) {
    const std::string sim = "simulate " + dir + "over-endpoint.json --json --certificates " + set;
    CHECK(run(sim).out.find("\"time_reached_exact\": \"7/2\"") != std::string::npos);
    const std::string until = run(sim + " --until 1").out;
    CHECK(until.find("\"stopped\": \"limit\"") != std::string::npos);
    CHECK(until.find("\"time_reached_exact\": \"1\"") != std::string::npos);
    CHECK(run(sim + " --events 0").out.find("\"time_reached_exact\": \"0\"") != std::string::npos);
  }
  CHECK(run("simulate " + dir + "turning-vertical.json --json").out.find("\"flip\": 1") != std::string::npos);
  // The three updates: the same batches; the local one counts its frontier
  // replays, the subtree one none.
  const Run local = run("simulate " + dir + "random-100.json --events 60 --json"),
            subtree = run("simulate " + dir + "random-100.json --events 60 --json --update subtree");
  REQUIRE(local.status == 0);
  REQUIRE(subtree.status == 0);
  CHECK(local.out.find("\"update\": \"local\"") != std::string::npos);
  CHECK(subtree.out.find("\"update\": \"subtree\"") != std::string::npos);
  CHECK(subtree.out.find("\"replays\": {\"frontier\": 0,") != std::string::npos);
  CHECK(local.out.find("\"replays\": {\"frontier\": 0,") == std::string::npos);
  CHECK(run("simulate " + dir + "random-100.json --events 60 --update subtree").out.find("replays:       0 at the frontier") !=
        std::string::npos);
  const Run triangles = run("simulate " + std::string(KVD_SOURCE_DIR) + "/data/two-triangles.json --update subtree", "2>&1");
  CHECK(triangles.status == 2);
  CHECK(triangles.out.find("--update subtree: a triangle scene takes local, reinsert or rebuild") != std::string::npos);
  // Flags of triangle scenes, a time outside the span: usage errors.
  const Run queue = run("simulate " + dir + "over-endpoint.json --queue heap", "2>&1");
  CHECK(queue.status == 2);
  CHECK(queue.out.find("--queue: only for triangle scenes") != std::string::npos);
  CHECK(run("build " + dir + "two-crossing.json --bsp").status == 2);
  CHECK(run("simulate " + dir + "over-endpoint.json --validate end").status == 2);
  const Run late = run("build " + dir + "over-endpoint.json --time 9", "2>&1");
  CHECK(late.status == 2);
  CHECK(late.out.find("--time 9 is outside the scene's time span [0, 7/2]") != std::string::npos);
}

// The run on seed 003's own certificates: the same edge event of
// over-endpoint.json, found by the certificate of the endpoint it passes
// over; on a random scene the same changes of the tree at the same instants
// as the kept run (tests/test_aeg_kinetic.cpp checks the trees); bad flags.
TEST_CASE("kvd simulate --certificates paper runs a segment scene on the paper's certificates", "[cli][simulate][segments]") {
  const std::string dir = std::string(KVD_SOURCE_DIR) + "/data/segments/";
  const Run list = run("simulate " + dir + "over-endpoint.json --certificates paper --list");
  REQUIRE(list.status == 0);
  CHECK(list.out.find("t = 3 (3): endpoint s0.1; tree changed\n") != std::string::npos);
  CHECK(list.out.find("failures:      1 (0 transient, 1 endpoint, 0 flip)") != std::string::npos);
  const Run json = run("simulate " + dir + "over-endpoint.json --certificates paper --json --list");
  REQUIRE(json.status == 0);
  CHECK(json.out.find(R"("certificate_set": "paper", "segments": 2, "batches": 1, "failures": 1, )"
                      R"("failures_by_kind": {"transient": 0, "endpoint": 1, "flip": 0}, "changed_batches": 1)") !=
        std::string::npos);
  CHECK(json.out.find(R"("validations": 1, "validation_failures": 0)") != std::string::npos);
  CHECK(json.out.find(R"("failing": [{"kind": "endpoint", "of": "s0.1"}], "changed": true)") != std::string::npos);
  // The certificates made again in the batch, the failing one among them,
  // and their median, mean and max over the run (here the same).
  const std::size_t made_at = json.out.find(R"("nodes_edited": 0, "certificates_made": )");
  REQUIRE(made_at != std::string::npos);
  const int made = std::stoi(json.out.substr(made_at + 40));
  CHECK(made >= 1);
  CHECK(json.out.find(R"(, "max": )" + std::to_string(made) + "}") != std::string::npos);
  // A flip fails the segment's certificate and the cell between its endpoints.
  CHECK(run("simulate " + dir + "rotating-10.json --certificates paper --list --events 2").out.find(
            "transient between s1.0 and s1.1; flip s1; tree changed") != std::string::npos);
  // Every flip of rotating-10.json is a lone one, done in place.
  const Run rotating = run("simulate " + dir + "rotating-10.json --certificates paper --json");
  REQUIRE(rotating.status == 0);
  const std::size_t flip_at = rotating.out.find("\"flip\": "), in_place_at = rotating.out.find("\"flips_in_place\": ");
  REQUIRE(flip_at != std::string::npos);
  REQUIRE(in_place_at != std::string::npos);
  const int flips = std::stoi(rotating.out.substr(flip_at + 8)), in_place = std::stoi(rotating.out.substr(in_place_at + 18));
  CHECK(flips > 0);
  CHECK(in_place == flips);
  // Up to t = 1/4 on 100 random segments, both runs change the tree in the same batches.
  const auto field = [](const std::string& out, const std::string& name) {
    const std::size_t at = out.find("\"" + name + "\": ");
    return at == std::string::npos ? std::string() : out.substr(at, out.find(',', at) - at);
  };
  const Run paper = run("simulate " + dir + "random-100.json --certificates paper --until 1/4 --events 100000 --json"),
            kept = run("simulate " + dir + "random-100.json --until 1/4 --events 100000 --json");
  REQUIRE(paper.status == 0);
  REQUIRE(kept.status == 0);
  CHECK(!field(paper.out, "changed_batches").empty());
  for (const char* f : {"batches", "changed_batches", "time_reached_exact", "nodes"}) CHECK(field(paper.out, f) == field(kept.out, f));
  for (const auto& [flags, message] :
       {std::pair{"--certificates paper --kernel double", "--certificates paper runs in the exact kernel only"},
        std::pair{"--certificates paper --update subtree", "--certificates paper has an update of its own"},
        std::pair{"--certificates reduced", "--certificates expects kept or paper"}}) {
    const Run bad = run("simulate " + dir + "over-endpoint.json " + flags, "2>&1");
    CHECK(bad.status == 2);
    CHECK(bad.out.find(message) != std::string::npos);
  }
  const Run triangles = run("simulate " + std::string(KVD_SOURCE_DIR) + "/data/two-triangles.json --certificates paper", "2>&1");
  CHECK(triangles.status == 2);
  CHECK(triangles.out.find("--certificates expects reduced or full") != std::string::npos);
}

TEST_CASE("kvd diff compares a segment scene's exact run with a floating-point one, or refuses bad input",
          "[cli][diff][segments]") {
  const std::string scene = std::string(KVD_SOURCE_DIR) + "/data/segments/over-endpoint.json";
  CHECK(run("diff --help").out.find("kvd-segments/1") != std::string::npos);
  // The one edge event at t = 3, found at exactly 3 in MPFR, the same tree after it.
  const Run r = run("diff " + scene + " --kernel mpfr:64 --json");
  REQUIRE(r.status == 0);
  CHECK(r.out.find(R"({"event": 0, "certificate": "side", "event_kind": "edge", "features": "s0.1 s1", )"
                   R"("exact_time": "3", "exact_approx": "3", "inexact_event": 0, )"
                   R"("inexact_time": "3.0000000000000000e+00", "in_order": true, "structure_equal": true, )"
                   R"("time_error": 0, "relative_time_error": 0})") != std::string::npos);
  CHECK(r.out.find("\"events_compared\": 1,\n\"first_divergence_event\": null,") != std::string::npos);
  CHECK(r.out.find("\"recovery\": {\"failed_builds\": 0, \"refires\": 0, \"stale_trees\": 0, \"rebuilds\": 0") !=
        std::string::npos);
  CHECK(run("diff " + scene + " --kernel double").out.find("event 0 side (edge) s0.1 s1 at 3: double event 0 at 3, error 0") !=
        std::string::npos);
  CHECK(r.out.find("\"inexact_stopped\": \"exhausted\"") != std::string::npos);
  // A double run stuck at its start (an epsilon that swamps the scene's
  // numbers) misses every exact event, and the report says why: the diff
  // used to show only the missed events, with no word of the run stuck.
  const std::string random = std::string(KVD_SOURCE_DIR) + "/data/segments/random-100.json";
  const Run stuck = run("diff " + random + " --kernel double --epsilon 1 --events 10 --json");
  CHECK(stuck.status == 0);  // divergence is a finding
  CHECK(stuck.out.find("\"missed_events\": 10,") != std::string::npos);
  CHECK(stuck.out.find("\"inexact_stopped\": \"stuck\"") != std::string::npos);
  CHECK(run("diff " + random + " --kernel double --epsilon 1 --events 10").out.find("stopped:              double run stuck (") !=
        std::string::npos);
  const Run kernel = run("diff " + scene + " --kernel bogus", "2>&1");
  CHECK(kernel.status == 2);
  CHECK(kernel.out.find("unknown kernel 'bogus'") != std::string::npos);
  // The viewer reads a diff report with triangle scenes only: the diff of a
  // segment scene is refused, as are the triangle page's flags.
  const std::string page = std::string(KVD_BINARY_DIR) + "/segments-view.html";
  std::remove(page.c_str());
  const std::string report = std::string(KVD_BINARY_DIR) + "/segments-diff.json";
  REQUIRE(run("diff " + scene + " --kernel double --json > " + report).status == 0);
  const Run refused = run("view " + report + " --out " + page, "2>&1");
  CHECK(refused.status == 2);
  CHECK(refused.out.find("is a segment scene (kvd-segments/1)") != std::string::npos);
  for (const std::string flag : {"--collisions stop", "--view 1,2,3", "--until 11", "--allow-intersecting"}) {
    const Run r = run("view " + scene + " " + flag + " --out " + page, "2>&1");
    CHECK(r.status == 2);
    CHECK(r.out.find(flag.substr(0, flag.find(' '))) != std::string::npos);
  }
  CHECK(!std::ifstream(page).good());
  // --scene names a trace's scene, not a scene's.
  const Run given = run("view " + scene + " --scene " + scene + " --out " + page, "2>&1");
  CHECK(given.status == 2);
  CHECK(given.out.find("--scene is for a trace") != std::string::npos);
  CHECK(!std::ifstream(page).good());
  // A segment scene's page (its contents: test_segment_page), from a file
  // and from standard input, read once.
  const Run viewed = run("view " + scene + " --out " + page);
  CHECK(viewed.status == 0);
  CHECK(viewed.out.find("kvd view: 1 batches, 1 events; wrote " + page) != std::string::npos);
  CHECK(std::ifstream(page).good());
  const Run piped = run("view - --out " + page + " < " + scene);
  CHECK(piped.status == 0);
  CHECK(piped.out.find("kvd view: 1 batches, 1 events; wrote " + page) != std::string::npos);
  const Run flag = run("diff " + scene + " --kernel double --allow-intersecting", "2>&1");
  CHECK(flag.status == 2);
  CHECK(flag.out.find("--allow-intersecting: only for triangle scenes") != std::string::npos);
  const std::string bad = scene_file("bad-diff-segments.json", R"({"format": "kvd-segments/1", "segments": [
    {"endpoints": [["0", "0"], ["1", "x"]]}]})");
  const Run message = run("diff " + bad + " --kernel double", "2>&1");
  CHECK(message.status == 2);
  CHECK(message.out.find(bad + ": /segments/0/endpoints/1/1: ") != std::string::npos);
}

namespace {

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("kvd certify writes a segment scene's certificate, or nothing on bad input", "[cli][certify][segments]") {
  const std::string scene = std::string(KVD_SOURCE_DIR) + "/data/segments/over-endpoint.json";
  const std::string out = std::string(KVD_BINARY_DIR) + "/over-endpoint.cert.json";
  std::remove(out.c_str());
  CHECK(run("certify --help").out.find("kvd-segment-event-order/1") != std::string::npos);
  CHECK(run("certify " + scene + " --out " + out + " --collisions stop").status == 2);
  CHECK(run("certify " + scene + " --out " + out + " --validate end").status == 2);
  CHECK(run("certify " + scene + " --out " + out + " --until 4").status == 2);  // after the span's end, 7/2
  const std::string bad = scene_file("bad-certify-segments.json", R"({"format": "kvd-segments/1", "segments": [
    {"endpoints": [["0", "0"], ["0", "0"]]}]})");
  const Run message = run("certify " + bad + " --out " + out, "2>&1 >/dev/null");
  CHECK(message.status == 2);
  CHECK(message.out.find(bad + ": /segments/0: ") != std::string::npos);
  CHECK(!std::ifstream(out).good());
  // The sinker passes over the floor's right endpoint at t = 3; the last
  // interval runs to the span's end.
  const Run r = run("certify " + scene + " --validate every --out " + out);
  CHECK(r.status == 0);
  CHECK(r.out.find("1 events in 1 batches") != std::string::npos);
  const std::string text = file_text(out);
  CHECK(text.rfind("{\n\"format\": \"kvd-segment-event-order/1\"", 0) == 0);
  CHECK(text.find("\"end\": \"7/2\",\n\"stopped_by\": \"exhausted\"") != std::string::npos);
  CHECK(text.find(R"({"certificate": 6, "factor": 0, "interval": ["3", "3"], "multiplicity": 1, "order": "<"})") !=
        std::string::npos);
}

TEST_CASE("kvd render draws a segment scene's BSP as SVG, one element per cut", "[cli][render][segments]") {
  const std::string dir = std::string(KVD_SOURCE_DIR) + "/data/segments/";
  const std::string out = std::string(KVD_BINARY_DIR) + "/render-segments.svg";
  for (const auto& [scene, time] : {std::pair{"two-crossing", "0"}, std::pair{"over-endpoint", "13/4"}}) {
    INFO(scene);
    std::remove(out.c_str());
    const std::string args = dir + scene + ".json --time " + time;
    const nlohmann::json counts = nlohmann::json::parse(run("build " + args + " --json").out);
    REQUIRE(run("render " + args + " -o " + out).status == 0);
    const std::string svg = file_text(out);
    CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
    CHECK(occurrences(svg, "class=\"vertex-cut\"") == counts["vertex_cuts"].get<std::size_t>());
    CHECK(occurrences(svg, "class=\"intersection-cut\"") == counts["intersection_cuts"].get<std::size_t>());
    CHECK(occurrences(svg, "class=\"edge-cut\"") == counts["edge_cuts"].get<std::size_t>());
    CHECK(occurrences(svg, "class=\"cell ") == counts["leaves"].get<std::size_t>());
    CHECK(run("render " + args).out == svg);  // the same bytes on stdout
  }
  CHECK(run("render --help").out.find("kvd-segments/1") != std::string::npos);
}

TEST_CASE("kvd render and kvd animate refuse bad input for segment scenes and write nothing",
          "[cli][render][animate][segments]") {
  const std::string scene = std::string(KVD_SOURCE_DIR) + "/data/segments/two-crossing.json";
  const std::string out = std::string(KVD_BINARY_DIR) + "/refused-segments.svg";
  std::remove(out.c_str());
  const Run late = run("render " + scene + " --time 11 -o " + out, "2>&1");  // the span is [0, 10]
  CHECK(late.status == 2);
  CHECK(late.out.find("--time 11 is outside the scene's time span [0, 10]") != std::string::npos);
  CHECK(run("render " + scene + " --time -1/2 -o " + out).status == 2);
  const Run view = run("render " + scene + " --view 1,2,3 -o " + out, "2>&1");
  CHECK(view.status == 2);
  CHECK(view.out.find("--view: only for triangle scenes") != std::string::npos);
  CHECK(run("render " + scene + " --cells -o " + out).status == 2);
  CHECK(run("render " + scene + " -o " + std::string(KVD_BINARY_DIR) + "/refused-segments.png").status == 2);
  CHECK(run("animate " + scene + " --view 1,2,3 -o " + out).status == 2);
  CHECK(run("animate " + scene + " --until 11 -o " + out).status == 2);
  CHECK(run("animate " + scene + " -o " + std::string(KVD_BINARY_DIR) + "/refused-segments.gif").status == 2);
  CHECK(!std::ifstream(out).good());
}

TEST_CASE("kvd animate films a segment scene's run, a held frame after each batch", "[cli][animate][segments]") {
  const std::string scene = std::string(KVD_SOURCE_DIR) + "/data/segments/over-endpoint.json";
  const std::string out = std::string(KVD_BINARY_DIR) + "/over-endpoint-film.svg";
  std::remove(out.c_str());
  // One batch (the edge event at t = 3): four sampled frames and one held.
  const Run r = run("animate " + scene + " --frames 4 -o " + out);
  CHECK(r.status == 0);
  CHECK(r.out.find("1 batches, 1 events, 5 pictures in 9 frames") != std::string::npos);
  const std::string film = file_text(out);
  CHECK(occurrences(film, "<g class=\"frame\"") == 5);
  CHECK(occurrences(film, "data-batch=\"0\"") == 1);
  CHECK(film.find("after batch 1 of 1 (t = 3): edge event") != std::string::npos);
  CHECK(occurrences(film, "<style>") == 1);
}

TEST_CASE("kvd animate films only the start of a run stopped for its events before any batch", "[cli][animate]") {
  const std::string out = std::string(KVD_BINARY_DIR) + "/no-events-film.svg";
  for (const char* scene : {"segments/over-endpoint", "two-triangles"}) {
    INFO(scene);
    std::remove(out.c_str());
    const Run none = run("animate " + std::string(KVD_SOURCE_DIR) + "/data/" + scene + ".json --frames 4 --events 0 -o " + out);
    CHECK(none.status == 0);
    CHECK(none.out.find("0 batches, 0 events, 1 pictures in 1 frames") != std::string::npos);
    CHECK(std::ifstream(out).good());
  }
}

TEST_CASE("kvd bench aeg measures the BSP of segments against seed 003's bounds, or writes nothing on bad input",
          "[cli][bench]") {
  const std::string out = std::string(KVD_BINARY_DIR) + "/bench-aeg";
  const std::string to = " --out " + out;
  std::remove((out + "/aeg.md").c_str());
  std::remove((out + "/aeg.csv").c_str());
  CHECK(run("bench aeg --help").out.find("usage: kvd bench aeg") != std::string::npos);
  CHECK(run("bench aeg --sizes 0" + to).status == 2);
  CHECK(run("bench aeg --kinetic-sizes 20,x" + to).status == 2);
  CHECK(run("bench aeg --repeats 0" + to).status == 2);
  CHECK(run("bench aeg --events x" + to).status == 2);
  CHECK(run("bench aeg --rotating-long 10,x" + to).status == 2);
  CHECK(!std::ifstream(out + "/aeg.md").good());
  const Run r = run("bench aeg --sizes 20,10 --quadratic-up-to 10 --kinetic-sizes 10 --events 10 --rotating 10 --rotating-long 12,10 --repeats 1" +
                    to);
  REQUIRE(r.status == 0);
  std::ifstream f(out + "/aeg.md");
  const std::string md((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  // The sizes in increasing order, long segments only up to 10, and the
  // local update agreeing with the rebuild.
  CHECK(md.find("| linear | 10 | ") < md.find("| linear | 20 | "));
  CHECK(md.find("| quadratic | 10 | ") != std::string::npos);
  CHECK(md.find("| quadratic | 20 | ") == std::string::npos);
  CHECK(md.find("**no**") == std::string::npos);
  // One row per configuration; every static tree has the paper's 2n vertex
  // cuts and 2k intersection cuts (seed 003, section 2.1).
  std::ifstream c(out + "/aeg.csv");
  std::string header, line;
  std::getline(c, header);
  std::vector<std::string> names;
  for (std::stringstream hs(header); std::getline(hs, line, ',');) names.push_back(line);
  std::map<std::string, int> rows;
  while (std::getline(c, line)) {
    std::map<std::string, std::string> v;
    std::stringstream ls(line);
    for (const std::string& n : names) std::getline(ls, v[n], ',');
    INFO(line);
    CHECK(std::count(line.begin(), line.end(), ',') == std::count(header.begin(), header.end(), ','));
    ++rows[v["part"]];
    if (v["part"] != "static") continue;
    CHECK(std::stoul(v["vertex_cuts"]) == 2 * std::stoul(v["n"]));
    CHECK(std::stoul(v["intersection_cuts"]) == 2 * std::stoul(v["k"]));
  }
  CHECK(rows["static"] == 3);   // linear 10 and 20, quadratic 10
  CHECK(rows["kinetic"] == 7);  // m = 10 and 5, short and long segments, and the three rotating scenes
  // The rotating scenes flip, and have a row each in the flips' table, the
  // long ones in increasing size.
  const std::string flips = md.substr(md.find("## Flip events"));
  CHECK(flips.find("| rotating | 10 | ") != std::string::npos);
  CHECK(flips.find("| rotating, long segments | 10 | ") < flips.find("| rotating, long segments | 12 | "));
  CHECK(flips.find("| rotating, long segments | 12 | ") != std::string::npos);
}

TEST_CASE("kvd bench aeg-cost counts an event's cost of both segment runs, or writes nothing on bad input",
          "[cli][bench]") {
  const std::string out = std::string(KVD_BINARY_DIR) + "/bench-aeg-cost";
  const std::string to = " --out " + out;
  std::remove((out + "/aeg-cost.md").c_str());
  std::remove((out + "/aeg-cost.csv").c_str());
  CHECK(run("bench aeg-cost --help").out.find("usage: kvd bench aeg-cost") != std::string::npos);
  CHECK(run("bench aeg-cost --sizes 0" + to).status == 2);
  CHECK(run("bench aeg-cost --events x" + to).status == 2);
  CHECK(run("bench aeg-cost --flip-sizes 1,x" + to).status == 2);
  CHECK(!std::ifstream(out + "/aeg-cost.md").good());
  REQUIRE(run("bench aeg-cost --sizes 20,10 --flip-sizes 30 --events 400" + to).status == 0);
  std::ifstream f(out + "/aeg-cost.md");
  const std::string md((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  CHECK(md.find("| 10 | 10 | ") < md.find("| 20 | 20 | "));
  std::ifstream c(out + "/aeg-cost.csv");
  std::string header, line;
  std::getline(c, header);
  std::vector<std::string> names;
  for (std::stringstream hs(header); std::getline(hs, line, ',');) names.push_back(line);
  std::map<std::string, std::map<std::string, std::string>> rows;  // by family, run, n and m
  while (std::getline(c, line)) {
    std::map<std::string, std::string> v;
    std::stringstream ls(line);
    for (const std::string& n : names) std::getline(ls, v[n], ',');
    INFO(line);
    CHECK(std::stoul(v["batches"]) > 0);
    CHECK(std::stod(v["signs_median"]) <= std::stod(v["signs_max"]));
    CHECK(std::stod(v["nodes_made_median"]) <= std::stod(v["nodes_made_max"]));
    CHECK(std::stoul(v["flips_in_place"]) <= std::stoul(v["lone_flips"]));
    CHECK(std::stod(v["flip_nodes_median"]) <= std::stod(v["flip_nodes_max"]));
    CHECK(std::stod(v["flip_signs_median"]) <= std::stod(v["flip_signs_max"]));
    rows[v["family"] + " " + v["run"] + " " + v["n"] + " " + v["m"]] = v;
  }
  CHECK(rows.size() == 10);  // two runs of n = 10 and 20, all and half moving, and of 30 rotating
  // Rotating segments flip; random ones start with none vertical and do not turn.
  auto& rotating = rows["rotating paper 30 30"];
  CHECK(std::stoul(rotating["lone_flips"]) > 0);
  CHECK(std::stoul(rows["rotating local 30 30"]["lone_flips"]) > 0);
  CHECK(std::stod(rotating["flip_nodes_median"]) > 0);
  CHECK(md.find("| 30 | " + rotating["k"] + " | " + rotating["nodes"] + " | the paper's set | ") != std::string::npos);
  for (const char* scene : {"10 10", "10 5", "20 20", "20 10"}) {
    auto& local = rows[std::string("random local ") + scene];
    auto& paper = rows[std::string("random paper ") + scene];
    CHECK(local["lone_flips"] == "0");
    CHECK(paper["lone_flips"] == "0");
    INFO(scene);
    // One scene, one tree at the start; the paper's set holds no sign of
    // the construction, the kept one reads the signs it holds.
    CHECK(local["nodes"] == paper["nodes"]);
    CHECK(local["k"] == paper["k"]);
    CHECK(std::stod(paper["held_mean"]) == 0);
    CHECK(std::stod(local["held_mean"]) > 0);
    // Only the run on the paper's set remembers the signs of its instant.
    CHECK(std::stod(paper["repeated_mean"]) > 0);
    CHECK(std::stod(local["repeated_mean"]) == 0);
    // and tells where it decided them: some of its signs, never more.
    double phases = 0;
    for (const char* p :
         {"own_guard_mean", "other_guard_mean", "ties_mean", "certificates_mean", "leaves_mean", "walls_mean"}) {
      CHECK(local[p].empty());
      phases += std::stod(paper[p]);
    }
    CHECK(std::stod(paper["certificates_mean"]) > 0);
    CHECK(phases <= std::stod(paper["signs_mean"]) + 0.01);
    CHECK(std::stod(paper["other_guard_max"]) <= std::stod(paper["signs_max"]));
  }
}
