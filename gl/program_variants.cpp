#include "gl/program_variants.hpp"

#include "gl/program.hpp"

namespace clothlab::vis {

ProgramVariants::ProgramVariants(std::vector<std::string> files, const std::string& first_defines)
    : files_(std::move(files)) {
  get(first_defines);
}

GLuint ProgramVariants::get(const std::string& defines) {
  for (const auto& [key, program] : variants_)
    if (key == defines) return program.get();
  variants_.emplace_back(defines, build_program(files_, defines));
  return variants_.back().second.get();
}

}  // namespace clothlab::vis
