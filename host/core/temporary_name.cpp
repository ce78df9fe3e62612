#include "core/temporary_name.hpp"

#include <filesystem>

#include <unistd.h>

namespace lancer {

std::string temporary_template(const std::string& path) {
    namespace fs = std::filesystem;
    fs::path target(path);
    fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
    if (name_max <= 0) name_max = 255;
    const std::string suffix = ".XXXXXX";
    std::string name = target.filename().string();
    const std::size_t room = static_cast<std::size_t>(name_max) - 1 - suffix.size();  // 1: the leading dot
    if (name.size() > room) {
        std::size_t cut = room;
        while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;  // not inside a character
        name.resize(cut);
    }
    return (dir / ("." + name + suffix)).string();
}

}  // namespace lancer
