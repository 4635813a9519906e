// The reconstruction operation of the front ends (zdg reconstruct, the Python function
// reconstruct): oriented points in (normals estimated when the cloud has none), an implicit
// field on h Z^3, the digitization of its negative set with its Betti numbers, and the
// marching-cubes mesh (estimators/implicit_reconstruction.hpp).
//
//   reconstruct_operation   validation (kernel/points/point_cloud.hpp), PCA normals oriented
//                           over the MST when missing (estimators/point_normals.hpp, k =
//                           normals_k), the field, the digitization, the mesh. Each step is
//                           reported to the progress callback and timed.
//
// Errors: InvalidArgument (one line) for the cloud's and the methods' bad input (see those
// headers), for a grid of more than max_samples samples, for an empty reconstruction (no
// sample inside: the mesh would be empty).
#pragma once

#include <zdg/estimators/implicit_reconstruction.hpp>
#include <zdg/operations/progress.hpp>

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <map>
#include <string>

namespace zdg {

struct ReconstructOptions {
  ReconstructionOptions method;  ///< method and its parameters, threads
  double h = 0;                  ///< grid step (physical units)
  int margin = 3;                ///< samples added around the points' box on each side
  std::size_t normals_k = 10;    ///< neighbours of the PCA normals when the cloud has none
  std::string source = "points"; ///< names the cloud in messages (its path)
  ProgressCallback progress;
};

struct ReconstructResult {
  Reconstruction reconstruction;
  std::size_t points = 0;
  bool normals_estimated = false;
  std::size_t normal_components = 0; ///< of the MST orientation, when estimated
  ReconstructionOptions method;
  double h = 0;
  std::map<std::string, double> seconds, cpu_seconds;
};

ReconstructResult reconstruct_operation(PointCloud cloud, const ReconstructOptions& options);

/// {"points","normals":"given"|"estimated","normal_components"?,"method","h","grid":[nx,ny,nz],
/// "samples","inside","euler","betti":[b0,b1,b2],"mesh":{"vertices","faces"},
/// "parameters":{...},"seconds","cpu_seconds","threads"}.
nlohmann::json to_json(const ReconstructResult& r);

} // namespace zdg
