// SPDX-License-Identifier: Apache-2.0
// Replays fuzz inputs without libFuzzer: feeds every file named on the command
// line (folders: every file in them) to the target's LLVMFuzzerTestOneInput.
// Built with the ordinary compiler, so ctest replays the committed corpus.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

bool replay(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "cannot read %s\n", file.c_str());
    return false;
  }
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  int inputs = 0;
  bool ok = true;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path arg(argv[i]);
    if (std::filesystem::is_directory(arg)) {
      for (const auto& e : std::filesystem::directory_iterator(arg))
        if (e.is_regular_file()) ok = replay(e.path()) && ok, ++inputs;
    } else {
      ok = replay(arg) && ok;
      ++inputs;
    }
  }
  std::printf("replayed %d inputs\n", inputs);
  // An empty corpus is a mistake in the test, not a pass.
  return ok && inputs > 0 ? 0 : 1;
}
