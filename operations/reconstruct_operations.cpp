#include <zdg/arith/error.hpp>
#include <zdg/estimators/point_normals.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>
#include <zdg/operations/reconstruct_operations.hpp>

#include <nlohmann/json.hpp>

#include <string>

namespace zdg {

ReconstructResult reconstruct_operation(PointCloud cloud, const ReconstructOptions& o) {
  ReconstructResult r;
  OperationProgress progress(o.progress);
  validate_point_cloud(cloud, o.source);
  r.points = cloud.size();
  r.method = o.method;
  r.h = o.h;
  (void)grid_around(cloud, o.h, o.margin); // the grid's size is checked before any work
  if (!cloud.has_normals()) {
    progress.start("normals");
    PointNormalsOptions no;
    no.k = o.normals_k;
    no.threads = o.method.threads;
    const PointNormals n = point_normals(cloud, no, o.source);
    cloud.normals = n.normals;
    r.normals_estimated = true;
    r.normal_components = n.components;
    progress.done("normals", std::to_string(n.components) + " component(s)");
  }
  progress.start(to_string(o.method.method) + " field");
  r.reconstruction = reconstruct(cloud, o.h, o.method, o.margin);
  progress.done("reconstruction", std::to_string(r.reconstruction.mesh.face_count()) + " faces");
  if (r.reconstruction.inside_count == 0)
    throw InvalidArgument(o.source + ": the " + to_string(o.method.method) +
                          " reconstruction has no sample inside at h = " + std::to_string(o.h) +
                          " (check the normals' orientation, or use a smaller h)");
  r.seconds = std::move(progress.seconds);
  r.cpu_seconds = std::move(progress.cpu_seconds);
  return r;
}

nlohmann::json to_json(const ReconstructResult& r) {
  const auto& rec = r.reconstruction;
  const auto& g = rec.field.grid;
  const auto& m = r.method;
  nlohmann::json params = {{"k", m.k}};
  switch (m.method) {
  case ReconstructionMethod::winding:
    params["beta"] = m.winding_beta;
    params["exact"] = m.winding_exact;
    break;
  case ReconstructionMethod::rbf:
    params["centers"] = m.rbf_centers;
    params["offset"] = m.rbf_offset;
    break;
  case ReconstructionMethod::imls:
    params["radius"] = m.imls_radius;
    break;
  default:
    break;
  }
  nlohmann::json j = {{"points", r.points},
                      {"normals", r.normals_estimated ? "estimated" : "given"},
                      {"method", to_string(m.method)},
                      {"h", r.h},
                      {"grid", {g.nx, g.ny, g.nz}},
                      {"samples", std::to_string(g.size())},
                      {"inside", std::to_string(rec.inside_count)},
                      {"euler", std::to_string(rec.betti.euler)},
                      {"betti",
                       {std::to_string(rec.betti.b[0]), std::to_string(rec.betti.b[1]),
                        std::to_string(rec.betti.b[2])}},
                      {"mesh",
                       {{"vertices", std::to_string(rec.mesh.vertex_count())},
                        {"faces", std::to_string(rec.mesh.face_count())}}},
                      {"parameters", params},
                      {"seconds", r.seconds},
                      {"cpu_seconds", r.cpu_seconds},
                      {"threads", worker_count(m.threads, std::int64_t{1} << 30)}};
  if (r.normals_estimated) j["normal_components"] = r.normal_components;
  return j;
}

} // namespace zdg
