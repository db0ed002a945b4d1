// The fuzz target without libFuzzer, for compilers that have none (gcc):
// each seed file, then a fixed number of deterministic mutations of it (bit
// flips, byte overwrites, truncations, digits inserted into numbers), through
// LLVMFuzzerTestOneInput. Not coverage-guided; a bounded regression run that
// ctest can afford on every build.
//   shadelab_fuzz_replay MUTATIONS SEED...
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

std::vector<uint8_t> mutate(std::vector<uint8_t> bytes, std::mt19937& random) {
  if (bytes.empty()) return bytes;
  auto position = [&] {
    return std::uniform_int_distribution<size_t>(0, bytes.size() - 1)(random);
  };
  int edits = std::uniform_int_distribution<int>(1, 4)(random);
  for (int i = 0; i < edits && !bytes.empty(); ++i) {
    switch (random() % 4) {
      case 0:
        bytes[position()] ^= uint8_t(1u << (random() % 8));
        break;
      case 1:
        bytes[position()] = uint8_t(random());
        break;
      case 2:
        bytes.resize(position());
        break;
      default:
        bytes.insert(bytes.begin() + long(position()), uint8_t('0' + random() % 10));
        break;
    }
  }
  return bytes;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s MUTATIONS SEED...\n", argv[0]);
    return 2;
  }
  int mutations = std::atoi(argv[1]);
  std::mt19937 random(12345);  // fixed: the same inputs every run
  size_t runs = 0;
  for (int i = 2; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    std::vector<uint8_t> seed((std::istreambuf_iterator<char>(in)), {});
    if (seed.empty()) {
      std::fprintf(stderr, "cannot read seed %s\n", argv[i]);
      return 2;
    }
    LLVMFuzzerTestOneInput(seed.data(), seed.size());
    for (int m = 0; m < mutations; ++m) {
      std::vector<uint8_t> input = mutate(seed, random);
      LLVMFuzzerTestOneInput(input.data(), input.size());
    }
    runs += size_t(mutations) + 1;
  }
  std::printf("%zu inputs from %d seeds: no crash\n", runs, argc - 2);
  return 0;
}
