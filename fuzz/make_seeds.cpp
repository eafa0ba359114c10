// woven_fuzz_seeds DIR: writes the fuzz targets' seed corpora (seed_files.h) under DIR.
#include <exception>
#include <iostream>

#include "seed_files.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: woven_fuzz_seeds DIR\n";
        return 2;
    }
    try {
        woven::fuzz::writeSeedCorpora(argv[1]);
    } catch (const std::exception& e) {
        std::cerr << "woven_fuzz_seeds: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
