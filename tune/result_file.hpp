// A whole tune (Result) as a TOML file, every number exact: `clothlab tune --scheduler` runs the
// settings on a Dask cluster through the Python module (python/clothlab/remote_tune.py), which
// writes the measured table with write_result, and the command line reads it back with
// read_result to print, plot and write it as it does its own. The reference's positions are
// not kept: the table needs its error bound and cost only.
#pragma once

#include <string>

#include "tune/tune.hpp"

namespace clothlab::tune {

// Complete or absent; throws std::runtime_error naming the file on failure.
void write_result(const std::string& path, const Result& result);
// Throws std::runtime_error naming the file when it is missing or not a tune's result.
Result read_result(const std::string& path);

}  // namespace clothlab::tune
