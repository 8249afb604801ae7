// The TOML files tune writes (the solver.tolerance cache, tune/tolerance.hpp; a whole tune's
// result, tune/result_file.hpp): numbers kept exact, settings as family, label and --set lines,
// and a file written complete or not at all.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "tune/sampled_run.hpp"

namespace clothlab::tune::toml_io {

// A double as a TOML string that std::strtod reads back to the same bits (the system's toml++
// library rounds the last bits of some floats it parses).
std::string exact(double v);
std::string exact_list(const std::vector<double>& values);  // ["...", "..."]
// The value `exact` wrote (NaN when the node is missing or not a string).
double number(const toml::node_view<const toml::node>& n);
std::vector<double> numbers(const toml::node_view<const toml::node>& n);

void write_setting(std::ostream& out, const Setting& s);  // family, label and set lines
Setting setting_from(const toml::table& t);

// Writes `path` through a temporary file beside it renamed when complete, creating its folder;
// throws std::runtime_error naming the file on failure.
void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& body);

}  // namespace clothlab::tune::toml_io
