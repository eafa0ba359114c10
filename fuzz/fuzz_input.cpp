#include "fuzz_input.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "seed_files.h"

namespace woven::fuzz {

FuzzDir::FuzzDir() { writeCompanionFiles(dir_.path().string()); }

void showRefusal(const std::exception& e) {
    static const bool show = std::getenv("WOVEN_FUZZ_SHOW_ERRORS") != nullptr;
    if (show) std::cerr << "refused: " << e.what() << "\n";
}

std::vector<std::string> arguments(const uint8_t* data, size_t size) {
    std::vector<std::string> words{"woven"};
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (size_t start = 0; !text.empty() && start <= text.size();) {
        const size_t end = std::min(text.find('\0', start), text.size());
        words.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return words;
}

std::string FuzzDir::write(const std::string& name, const uint8_t* data, size_t size) const {
    const std::string path = dir_.file(name);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if (!out.flush()) throw std::runtime_error("fuzz: cannot write " + path);  // stops the run, saying why
    return path;
}

}  // namespace woven::fuzz
