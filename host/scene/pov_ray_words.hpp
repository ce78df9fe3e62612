#pragma once
// POV-Ray's words where lancer has another (docs/scene-format.md, "Porting from POV-Ray"): the
// hint an unknown key or object type gets when a POV-Ray user writes what they know.
#include <string>
#include <string_view>

namespace lancer {

// " (POV-Ray's phong is lancer's specular ...)", or "" for a word POV-Ray does not have.
std::string pov_ray_key_hint(std::string_view key);
std::string pov_ray_type_hint(std::string_view type);

}  // namespace lancer
