// `clothlab tune --scheduler ADDRESS` (docs/tuning.md, "Python and Dask"): the tune's runs go
// to a Dask cluster through the Python module. Debian's Python ($CLOTHLAB_PYTHON, else
// /usr/bin/python3) runs python/clothlab/remote_tune.py with the build's module on its path; it
// writes the whole table (tune/result_file.hpp), which is read back here, so that the command
// line prints, plots and writes it as it does a serial tune.
#pragma once

#include <optional>

#include "apps/clothlab/commands.hpp"
#include "tune/tune.hpp"

namespace clothlab::app {

struct RemoteTune {
  std::optional<tune::Result> result;
  int status = 0;  // when there is no result: 2 for a bad address, 1 otherwise
};

// Runs the tune of `args` on the scheduler `args.scheduler` names; the Python side's messages
// (progress, why it failed) go to stderr as they come.
RemoteTune tune_on_scheduler(const TuneArgs& args);

}  // namespace clothlab::app
