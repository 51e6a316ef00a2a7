// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the OBJ loader, through to the BVH the renderer builds. Any
// input must load or throw ObjError.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "toroid/scene/obj_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const toroid::ObjFile obj = toroid::parse_obj(text, "fuzz.obj");
    toroid::obj_to_group(obj)->divide(toroid::kObjBvhThreshold);
  } catch (const toroid::ObjError&) {
  }
  return 0;
}
