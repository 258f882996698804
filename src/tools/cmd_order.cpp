// kvd order SCENE --view X,Y,Z: the back-to-front list of triangle fragments.
#include <iostream>
#include <optional>

#include "cli.hpp"
#include "json_out.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/query/visibility.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/tree/build.hpp"

namespace kvd::cli {

namespace {
const char* const order_help =
    "usage: kvd order SCENE --view X,Y,Z [--time T] [--seed S] [--cull] [--json]\n"
    "\n"
    "Builds the KVD just after time T (default: the scene's start) with the\n"
    "exact kernel and lists its triangle fragments back to front as seen from\n"
    "the point (X, Y, Z): painting them in this order is correct. Every\n"
    "coordinate is an exact rational.\n"
    "\n"
    "  --cull   occlusion culling (thesis 8.2.4): the decomposition point z is\n"
    "           replaced by the viewpoint, so that every P- and E-cut passes\n"
    "           through the viewer, and the far subtree of every T-node is\n"
    "           skipped; prints the counts of the thesis's Figure 8.9\n"
    "  --json   {\"fragments\": [{\"triangle\": ID, \"vertices\": [[\"x\",\"y\",\"z\"], ...]}, ...]}\n"
    "           and, with --cull, \"culling\": {\"triangle_nodes_culled\", \"triangle_nodes_total\",\n"
    "           \"tree_nodes_culled\", \"tree_nodes_total\"}\n"
    "\n"
    "Exit status: 0 on success, 2 on a bad scene or bad usage.\n";
}  // namespace

int order(Args& args) {
  Scene_args sa;
  sa.wants_time = sa.wants_view = true;
  bool cull = false;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << order_help;
      return 0;
    }
    if (a == "--cull") cull = true;
    else if (!sa.take(args, a)) args.unknown(a);
  }
  scene::Scene s = sa.load_scene("order");
  const auto& view = sa.required_view("order");
  if (cull) s.z = {{scene::QPoly(view[0]), scene::QPoly(view[1]), scene::QPoly(view[2]), scene::QPoly(1)}};
  const mpq_class time = sa.time ? *sa.time : s.start;
  const bool json = sa.json;
  const Exact_kernel k;
  const predicates::Classifier<Exact_kernel> c(k, s);
  const tree::Kvd_tree t = build_tree("order", *sa.path, c, Exact_time(time));
  const Point4<mpq_class> eye{{view[0], view[1], view[2], mpq_class(1)}};
  const query::Culling culling =
      cull ? query::back_to_front_culled(c, t, time) : query::Culling{query::back_to_front(c, t, eye, time)};
  Json fragments = Json::array();
  for (int i : culling.order) {
    const tree::Node& n = t.nodes[static_cast<std::size_t>(i)];
    Json vertices = Json::array();
    for (const auto& v : std::get<tree::Triangle_fragment>(n.fragment).corners) {
      Json xyz = Json::array();
      for (const mpq_class& x : query::corner_at(c, v, time)) xyz.push_back(x.get_str());
      vertices.push_back(xyz);
    }
    fragments.push_back({{"triangle", n.cut.id}, {"vertices", vertices}});
  }
  if (json) {
    Json out = {{"fragments", fragments}};
    if (cull)
      out["culling"] = {{"triangle_nodes_culled", culling.triangle_nodes_culled},
                        {"triangle_nodes_total", culling.triangle_nodes_total},
                        {"tree_nodes_culled", culling.tree_nodes_culled},
                        {"tree_nodes_total", culling.tree_nodes_total}};
    std::cout << json_line(out) << "\n";
    return 0;
  }
  for (const Json& f : fragments) {
    std::cout << "triangle " << f["triangle"] << ":";
    for (const Json& xyz : f["vertices"])
      std::cout << " (" << xyz[0].get<std::string>() << " " << xyz[1].get<std::string>() << " "
                << xyz[2].get<std::string>() << ")";
    std::cout << "\n";
  }
  if (cull)
    std::cout << "culled: " << culling.triangle_nodes_culled << " of " << culling.triangle_nodes_total
              << " triangle nodes, " << culling.tree_nodes_culled << " of " << culling.tree_nodes_total
              << " tree nodes\n";
  return 0;
}

}  // namespace kvd::cli
