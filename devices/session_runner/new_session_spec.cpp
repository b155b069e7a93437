#include "devices/session_runner/new_session_spec.h"

#include <cstdint>

#include "core/common/error.h"
#include "devices/vicon/vicon_trigger.h"

namespace lmc::devices {

NewSessionSpec new_session_spec(const NewSessionFields& a) {
  NewSessionSpec spec;
  spec.subject.subject_id = a.subject;
  spec.subject.handedness = a.handedness;
  if (a.hand_length_mm > 0) spec.subject.hand_length_mm = a.hand_length_mm;
  if (a.hand_breadth_mm > 0) spec.subject.hand_breadth_mm = a.hand_breadth_mm;
  spec.operator_name = a.operator_name;
  spec.notes = a.notes;
  spec.protocol = a.protocol;
  // A short version of a protocol for demos and rehearsals; the manifest keeps what was used.
  if (a.seconds > 0) spec.duration_override_s = a.seconds;
  if (!a.vicon.empty()) {
    const ViconTriggerConfig vc = parse_vicon_target(a.vicon);
    spec.vicon = {{"host", vc.host}, {"port", vc.port}};
    if (!a.vicon_database.empty()) spec.vicon["database_path"] = a.vicon_database;
  } else if (!a.vicon_database.empty()) {
    // Silently dropping it would leave the operator believing Vicon is set up.
    throw Error("a Vicon database path was given without a Vicon target (HOST[:PORT])");
  }
  if (a.counterbalance >= 0) spec.counterbalance_seed = static_cast<std::uint64_t>(a.counterbalance);
  return spec;
}

}  // namespace lmc::devices
