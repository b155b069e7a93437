#include "core/io/pose_set_tsv.h"

#include <istream>
#include <ostream>

namespace lmc {

void write_pose_set(std::ostream&, const PoseSet&) {}
void save_pose_set(const std::filesystem::path&, const PoseSet&) {}
PoseSet parse_pose_set(std::istream&, const std::string&) { return {}; }
PoseSet load_pose_set(const std::filesystem::path&) { return {}; }

}  // namespace lmc
