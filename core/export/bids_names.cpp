#include "core/export/bids_names.h"

#include <algorithm>

namespace lmc {

std::string bids_label(const std::string& name) {
  std::string out;
  for (const char c : name) {
    const bool keep = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    if (keep) out += c;
  }
  return out;
}

int bids_run_index(int pose_code, int repetition) {
  return pose_code * 100 + repetition;
}

std::string bids_stem(const BidsEntities& e) {
  std::string s = bids_session_prefix(e.subject, e.session) + "_task-" + e.task;
  if (!e.tracksys.empty()) s += "_tracksys-" + e.tracksys;
  if (!e.acq.empty()) s += "_acq-" + e.acq;
  if (e.run > 0) s += "_run-" + std::to_string(e.run);
  return s;
}

std::string bids_subject_dir(const std::string& subject_label) {
  return "sub-" + subject_label;
}

std::string bids_session_dir(const std::string& subject_label, const std::string& session_label) {
  return session_label.empty() ? bids_subject_dir(subject_label)
                               : bids_subject_dir(subject_label) + "/ses-" + session_label;
}

std::string bids_session_prefix(const std::string& subject_label, const std::string& session_label) {
  return session_label.empty() ? bids_subject_dir(subject_label)
                               : bids_subject_dir(subject_label) + "_ses-" + session_label;
}

std::string bids_device_tracksys(int device_id) {
  return "LMC" + std::to_string(device_id);
}

std::string bids_anonymous_label(int index, int count) {
  const size_t width = std::max<size_t>(2, std::to_string(std::max(count, 1)).size());
  std::string n = std::to_string(index + 1);
  if (n.size() < width) n.insert(0, width - n.size(), '0');
  return n;
}

}  // namespace lmc
