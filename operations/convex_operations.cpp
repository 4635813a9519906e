#include <zdg/operations/convex_operations.hpp>

#include <zdg/arith/error.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>

namespace zdg {

ConvexityDefinition convexity_definition_from_name(const std::string& name,
                                                   const std::string& option) {
  if (name == "full") return ConvexityDefinition::full;
  if (name == "hull") return ConvexityDefinition::hull;
  throw InvalidArgument(option + ": '" + name + "' (full or hull)");
}

const char* convexity_definition_name(ConvexityDefinition d) {
  return d == ConvexityDefinition::full ? "full" : "hull";
}

std::size_t distinct_point_count(int dim, const std::vector<BigInt>& coords) {
  const auto d = static_cast<std::size_t>(dim);
  std::vector<std::vector<BigInt>> v;
  v.reserve(coords.size() / d);
  for (std::size_t k = 0; k + d <= coords.size(); k += d)
    v.emplace_back(coords.begin() + static_cast<std::ptrdiff_t>(k),
                   coords.begin() + static_cast<std::ptrdiff_t>(k + d));
  std::sort(v.begin(), v.end());
  return static_cast<std::size_t>(std::unique(v.begin(), v.end()) - v.begin());
}

ConvexCheckResult convex_check_operation(const ConvexCheckOptions& o) {
  if (o.max_columns == 0) throw InvalidArgument("max_columns: 0 (at least 1)");
  auto r = digital_convexity_exact(o.dim, o.coords, o.definition, o.max_columns);
  ConvexCheckResult out;
  out.check = std::move(r.value);
  out.definition = o.definition;
  out.dim = o.dim;
  out.points = distinct_point_count(o.dim, o.coords);
  out.served = r.served;
  return out;
}

nlohmann::json to_json(const ConvexCheckResult& r) {
  const auto& c = r.check;
  nlohmann::json j{{"convex", c.convex},
                   {"definition", convexity_definition_name(r.definition)},
                   {"dimension", r.dim},
                   {"points", r.points},
                   {"integer_type", std::string(to_string(r.served))}};
  if (!c.convex) {
    nlohmann::json kh = nlohmann::json::array(), verts = nlohmann::json::array();
    for (const auto& k : c.witness_khalimsky) kh.push_back(k.str());
    for (const auto& v : c.witness_vertices) {
      nlohmann::json p = nlohmann::json::array();
      for (const auto& x : v) p.push_back(x.str());
      verts.push_back(p);
    }
    nlohmann::json w{{"dimension", c.witness_dimension}, {"khalimsky", kh}, {"vertices", verts}};
    if (c.witness_dimension == 0) w["point"] = verts[0];
    j["witness"] = w;
  }
  return j;
}

} // namespace zdg
