// What a path ClothLab writes to may name. Every file is written to a temporary file beside the
// path and renamed over it when complete (complete or absent), so the path must name a regular
// file or nothing: renaming over a device node, a pipe or a symbolic link would replace it (run
// as root, `--out /dev/stdout` replaced the system's device entry), and over a directory fails
// only after the whole run. Refused when the command line is read (exit 2).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace clothlab::app {

// Why `path` cannot be written by renaming a finished file over it (one line), or "" when it
// can: a file's directory must exist and be writable. `directory_ok`: the option also takes a
// directory (bench --out, render --out), made when missing.
std::string output_path_problem(const std::string& path, bool directory_ok);

// The same as a CLI11 check for a file option (trace --out, render --video, --music-out) or an
// option that takes a file or a directory (bench --out) or only a directory (render --out).
CLI::Validator output_file();
CLI::Validator output_file_or_directory();

}  // namespace clothlab::app
