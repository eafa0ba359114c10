#pragma once
// What the fuzz targets share: a private directory that holds the input under the name a loader
// expects, beside the small valid files the input may refer to (seed_files.h), and the rule for
// what counts as a finding.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "temp_dir.h"

namespace woven::fuzz {

// A temporary directory for one fuzzing process, removed when it ends normally.
class FuzzDir {
public:
    FuzzDir();  // holds the companion files of seed_files.h
    // Writes `data` to `name` in the directory (replacing it) and returns its path.
    std::string write(const std::string& name, const uint8_t* data, size_t size) const;
    std::string file(const std::string& name) const { return dir_.file(name); }

private:
    test::TempDir dir_;
};

void showRefusal(const std::exception& e);

// The bytes as a command line: the words between NUL bytes (no argument can hold one), after
// argv[0] "woven". A command-line target's seeds are written so (seed_files.h).
std::vector<std::string> arguments(const uint8_t* data, size_t size);

// Runs `parse` on one input. Refusing bad input by throwing is what woven does, so any
// std::exception is fine except std::bad_alloc: every size is checked before it is allocated
// (issue 15), so running out of memory is a bug and is left to abort the process. Crashes,
// sanitizer reports, hangs (-timeout) and memory beyond -rss_limit_mb are findings too.
// With WOVEN_FUZZ_SHOW_ERRORS set, each refusal's message is printed (is a seed accepted?).
template <typename Parse>
void refusalsAreFine(Parse&& parse) {
    try {
        parse();
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        showRefusal(e);
    }
}

}  // namespace woven::fuzz
