#include "gl/program.hpp"

#include <regex>

#include "gl/gl_error.hpp"
#include "gl/shader_sources.hpp"

namespace clothlab::vis {

std::string shader_text(const std::string& name) {
  for (const ShaderSource& s : embedded_shaders())
    if (name == s.name) return s.text;
  throw ShaderError("shaders/" + name + ": no such shader was embedded at build time");
}

std::string expand_includes(const std::string& text, const std::string& file,
                            std::vector<std::string>& files) {
  static const std::regex include(R"re(^\s*#include\s+"([^"]+)"\s*$)re");
  files = {file};
  std::string out;
  std::size_t line_number = 0, start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    ++line_number;
    std::smatch m;
    if (std::regex_match(line, m, include)) {
      files.push_back(m[1]);
      out += "#line 1 " + std::to_string(files.size() - 1) + "\n" + shader_text(m[1]) + "\n";
      out += "#line " + std::to_string(line_number + 1) + " 0\n";
    } else {
      out += line + "\n";
    }
    start = end + 1;
  }
  return out;
}

std::string annotate_shader_log(const std::string& log, const std::vector<std::string>& files) {
  static const std::regex location(R"((^|\n)(\d+)[:(](\d+)\)?(\((\d+)\))?\s*:)");
  std::string out;
  auto begin = log.cbegin();
  for (std::sregex_iterator it(log.begin(), log.end(), location), end; it != end; ++it) {
    const std::smatch& m = *it;
    out.append(begin, m[0].first);
    const auto source = static_cast<std::size_t>(std::stoul(m[2]));
    const std::string name = source < files.size() ? files[source] : files.front();
    out.append(m[1].str()).append("shaders/").append(name).append(":").append(m[3].str());
    if (m[5].matched) out.append(":").append(m[5].str());
    out.append(":");
    begin = m[0].second;
  }
  out.append(begin, log.cend());
  return out;
}

namespace {

std::string info_log(GLuint name, bool program) {
  GLint length = 0;
  program ? glGetProgramiv(name, GL_INFO_LOG_LENGTH, &length)
          : glGetShaderiv(name, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  program ? glGetProgramInfoLog(name, length, nullptr, log.data())
          : glGetShaderInfoLog(name, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

GLenum stage_of(const std::string& file) {
  if (file.ends_with(".vert")) return GL_VERTEX_SHADER;
  if (file.ends_with(".geom")) return GL_GEOMETRY_SHADER;
  if (file.ends_with(".frag")) return GL_FRAGMENT_SHADER;
  if (file.ends_with(".comp")) return GL_COMPUTE_SHADER;
  throw ShaderError("shaders/" + file +
                    ": unknown shader stage (expected .vert, .geom, .frag, .comp)");
}

// `defines` after the first line (#version), then a #line directive so that the stage's next
// line is still its line 2 of source string 0.
std::string with_defines(const std::string& text, const std::string& defines) {
  if (defines.empty()) return text;
  const std::size_t end = text.find('\n');
  if (end == std::string::npos) return text + "\n" + defines;
  return text.substr(0, end + 1) + defines + "#line 2 0\n" + text.substr(end + 1);
}

}  // namespace

Program link_program(const std::vector<ShaderStage>& stages, const std::string& defines,
                     const std::vector<const char*>& captured) {
  std::vector<Shader> shaders;
  std::string names;
  for (const ShaderStage& stage : stages) {
    Shader shader(glCreateShader(stage.type));
    std::vector<std::string> files;
    const std::string expanded =
        with_defines(expand_includes(stage.text, stage.file, files), defines);
    const char* text = expanded.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    glCompileShader(shader.get());
    GLint ok = 0;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (!ok)
      throw ShaderError("shaders/" + stage.file + " does not compile:\n" +
                        annotate_shader_log(info_log(shader.get(), false), files));
    shaders.push_back(std::move(shader));
    names += (names.empty() ? "" : " + ") + stage.file;
  }
  Program program(glCreateProgram());
  for (const Shader& s : shaders) glAttachShader(program.get(), s.get());
  if (!captured.empty())  // one buffer binding per output, in the listed order
    glTransformFeedbackVaryings(program.get(), static_cast<GLsizei>(captured.size()),
                                captured.data(), GL_SEPARATE_ATTRIBS);
  glLinkProgram(program.get());
  GLint ok = 0;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  if (!ok)
    throw ShaderError("shaders " + names + " do not link:\n" + info_log(program.get(), true));
  for (const Shader& s : shaders) glDetachShader(program.get(), s.get());
  glObjectLabel(GL_PROGRAM, program.get(), -1, names.c_str());
  return program;
}

Program build_program(const std::vector<std::string>& files, const std::string& defines,
                      const std::vector<const char*>& captured) {
  std::vector<ShaderStage> stages;
  for (const std::string& f : files) stages.push_back({stage_of(f), f, shader_text(f)});
  return link_program(stages, defines, captured);
}

}  // namespace clothlab::vis
