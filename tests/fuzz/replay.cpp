// A driver for the fuzz targets without libFuzzer (any compiler): feeds every file of the
// given folders to LLVMFuzzerTestOneInput, then deterministic mutations of each (bytes
// flipped, cut, duplicated, replaced by interesting values). `make test` runs it on the
// corpus; scripts/fuzz.sh runs the real libFuzzer build.
//   replay [--mutations N] DIR...
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv) {
  int mutations = 200;
  std::vector<std::string> dirs;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--mutations") == 0 && i + 1 < argc)
      mutations = std::atoi(argv[++i]);
    else
      dirs.push_back(argv[i]);
  }
  std::mt19937 rng(12345);
  size_t files = 0, runs = 0;
  for (const std::string& d : dirs) {
    std::vector<std::filesystem::path> paths;
    for (const auto& e : std::filesystem::directory_iterator(d))
      if (e.is_regular_file()) paths.push_back(e.path());
    std::sort(paths.begin(), paths.end());
    for (const auto& p : paths) {
      std::ifstream f(p, std::ios::binary);
      const std::vector<uint8_t> seed((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
      LLVMFuzzerTestOneInput(seed.data(), seed.size());
      ++files;
      ++runs;
      static const uint8_t interesting[] = {0,   0xFF, 0x7F, 0x80, '9',  '-', '{',
                                            '}', '[',  ']',  '"',  '\n', '/', 'e'};
      for (int m = 0; m < mutations; ++m) {
        std::vector<uint8_t> v = seed;
        const int edits = 1 + int(rng() % 4);
        for (int e = 0; e < edits; ++e) {
          const size_t at = v.empty() ? 0 : rng() % v.size();
          switch (rng() % 5) {
            case 0:
              if (!v.empty()) v[at] ^= uint8_t(1u << (rng() % 8));
              break;
            case 1: v.resize(at); break;
            case 2:
              if (!v.empty())
                v.insert(v.begin() + long(at), v.begin() + long(at),
                         v.begin() + long(std::min(v.size(), at + 1 + rng() % 16)));
              break;
            case 3:
              if (!v.empty()) v[at] = interesting[rng() % sizeof interesting];
              break;
            default: v.insert(v.begin() + long(at), interesting[rng() % sizeof interesting]); break;
          }
        }
        LLVMFuzzerTestOneInput(v.data(), v.size());
        ++runs;
      }
    }
  }
  std::printf("replayed %zu files, %zu inputs, no crash\n", files, runs);
  return files > 0 ? 0 : 1;
}
