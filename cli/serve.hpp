// zdg serve's answers, apart from the command line: one JSON request line of an operation in,
// one JSON answer line out (cli/serve_handlers.cpp). Requests carry the
// operation's arguments under the lowercase names of `zdg OPERATION --help` (integers as
// decimal strings or JSON integers, images as nested lists); answers carry the fields of
// `zdg OPERATION --json`, or {"error": "..."} for a request zdg refuses (never an exception).
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace zdg::cli {

/// The operations answered ("floor-sum", "dss recognize", ...), sorted.
std::vector<std::string> serve_operations();

/// The answer (one line of JSON, no newline) to one request line of the operation.
/// InvalidArgument for an unknown operation (listing the known ones).
std::string serve_answer(const std::string& operation, const std::string& line);

} // namespace zdg::cli
