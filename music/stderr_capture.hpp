// What a library prints on stderr while a call runs, captured instead of shown: the decoders
// behind libsndfile (libmpg123's warnings on a damaged MP3) and the audio back-ends behind OpenAL
// (ALSA's lines when no sound device exists) print there. The text comes back as one line, which
// a failure's message quotes; on success it is dropped. Descriptor 2 is swapped for the
// capture's lifetime, so use it only where no other thread prints (loading a file, opening the
// audio device).
#pragma once

#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <string>

namespace clothlab {

class StderrCapture {
 public:
  StderrCapture() {
    std::fflush(stderr);
    file_ = std::tmpfile();
    saved_ = file_ ? ::dup(2) : -1;
    if (saved_ >= 0) ::dup2(::fileno(file_), 2);
  }
  ~StderrCapture() {
    restore();
    if (file_) std::fclose(file_);  // every read left one open descriptor (the fuzz pass: EMFILE)
  }
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;

  // What was printed, on one line (runs of white space folded to one space), at most 300 chars.
  std::string text() {
    restore();
    std::string out;
    if (!file_) return out;
    std::rewind(file_);
    for (int c; (c = std::fgetc(file_)) != EOF && out.size() < 300;) {
      const bool space = std::isspace(c) != 0;
      if (space && (out.empty() || out.back() == ' ')) continue;
      out.push_back(space ? ' ' : static_cast<char>(c));
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, 2);
    ::close(saved_);
    saved_ = -1;
  }
  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

}  // namespace clothlab
