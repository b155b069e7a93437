#pragma once
// What an operator types for a new subject session — on `lmc session new`'s command line or in the
// Record tab's set-up form — turned into the core's NewSessionSpec. One rule for both, so the two
// accept and refuse the same text (the Vicon target is parsed by the trigger's own parser; the
// subject id and hand sizes are checked again by SessionFolder::create, through core's rules).
#include <string>

#include "core/session/session_folder.h"

namespace lmc::devices {

struct NewSessionFields {
  std::string subject;
  std::string handedness = "right";  // right | left
  double hand_length_mm = 0;         // 0: not measured
  double hand_breadth_mm = 0;        // 0: not measured
  std::string operator_name;
  std::string notes;
  std::string protocol = "study";  // a name of assets/protocols/ or a path
  std::string vicon;               // "HOST[:PORT]"; empty: no Vicon trigger
  std::string vicon_database;      // the Vicon database the trials go into (optional)
  double seconds = 0;              // > 0: every trial this long (demos, rehearsals)
  long long counterbalance = -1;   // >= 0: the seed of a counterbalanced order
};

// Throws lmc::Error naming the field at fault (a Vicon port that is not a number, a database path
// without a Vicon target).
NewSessionSpec new_session_spec(const NewSessionFields& fields);

}  // namespace lmc::devices
