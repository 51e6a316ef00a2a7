// SPDX-License-Identifier: Apache-2.0
// `add: camera`: the one camera of a scene.
#include <numbers>
#include <sstream>

#include "toroid/render/image_limits.h"
#include "toroid/scene/item_builders.h"

namespace toroid {

void build_camera(LoadState& state, SceneParts& parts, ItemParams& item) {
  const Param add = item.get("add"), width = item.get("width"), height = item.get("height");
  const Param fov = item.get("field-of-view"), from = item.get("from"), to = item.get("to"), up = item.get("up");
  item.report_unused("a camera");
  const SceneReader& r = state.reader;
  if (parts.camera) r.fail(add.value(), "a second camera (only one is allowed)");
  CameraParams c;
  const YAML::Node& w = width.need("a camera");
  const YAML::Node& h = height.need("a camera");
  c.width = r.integer(w);
  c.height = r.integer(h);
  if (const std::string e = image_size_error(c.width, c.height); !e.empty())
    r.fail(c.width < 1 || c.width > kMaxImageSide ? w : h, "camera " + e);
  const YAML::Node& f = fov.need("a camera");
  c.fov = r.number(f);
  if (!(c.fov > 0 && c.fov < std::numbers::pi)) {
    // A view between pi and 180 is almost surely in degrees: say what it
    // would be in radians.
    std::string hint;
    if (c.fov > std::numbers::pi && c.fov < 180) {
      std::ostringstream meant;  // six significant digits, as %g
      meant << c.fov * (std::numbers::pi / 180);
      hint = "; if it is in degrees, write " + meant.str();
    }
    r.fail(f, "field-of-view must be between 0 and pi radians, got " + f.Scalar() + hint);
  }
  c.from = r.point3(from.need("a camera"), "from");
  c.to = r.point3(to.need("a camera"), "to");
  c.up = r.vector3(up.need("a camera"), "up");
  const Tuple fwd = c.to - c.from;
  if (magnitude(fwd) == 0) r.fail(to.value(), "camera 'to' equals 'from'");
  if (magnitude(cross(fwd, c.up)) <= 1e-12 * magnitude(fwd) * magnitude(c.up))
    r.fail(up.value(), "camera 'up' is zero or parallel to the view direction");
  parts.camera = c;
}

}  // namespace toroid
