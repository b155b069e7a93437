// lmc devices [--backend sim|leapc|replay:FILE] [--layout L] [--json] [--leapc-library PATH]
// [--wait S]: the controllers a backend reports, with serial number, backend, model and the layout
// slot each would fill (a serial bound in the layout → that slot; otherwise the next free slot in
// order of appearance, as the hub assigns them; "-" when none is left, i.e. the serial needs
// assigning). For leapc it first says which LeapC library it loaded from where, its version and
// the service's; when none is usable it fails with every place tried and why.
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/io/layout_json.h"
#include "devices/device_hub.h"
#include "devices/leapc/leapc_library.h"
#include "devices/source_factory.h"

namespace {

struct DevicesOptions {
  std::string backend = "sim";
  std::string layout = "paper-initial";
  std::string sim_config;
  bool json = false;
  std::string leapc_library;  // --leapc-library
  double wait_s = 1.5;        // leapc: how long to listen for controllers
};

// The LeapC library the backend will load, or lmc::Error with every place tried.
std::shared_ptr<const lmc::devices::LeapcLibrary> leapc_library_or_fail(const DevicesOptions& opt) {
  if (!opt.leapc_library.empty()) lmc::devices::set_leapc_library_path(opt.leapc_library);
  lmc::devices::LeapcSearchResult found = lmc::devices::find_leapc();
  if (!found.library) throw lmc::Error("LeapC: " + found.failure_text());
  return found.library;
}

void run_devices(const DevicesOptions& opt) {
  using namespace lmc::devices;
  const SourceSpec spec = parse_source_spec(opt.backend);
  SourceSettings settings;
  settings.layout = lmc::load_layout_or_preset(opt.layout);
  if (!opt.sim_config.empty()) settings.sim = load_sim_config(opt.sim_config);
  std::shared_ptr<const LeapcLibrary> library;
  std::vector<std::string> notices;
  if (spec.backend == "leapc") {
    library = leapc_library_or_fail(opt);
    settings.leapc_wait_ms = static_cast<std::uint32_t>(opt.wait_s * 1000.0);
    settings.leapc_notices = &notices;
  }
  const std::vector<DeviceInfo> devices = list_devices(spec, settings);

  // The hub's own mapping decides the slots, so this listing and a recording agree.
  DeviceHub hub(settings.layout);
  for (const auto& d : devices) {
    DeviceEvent e;
    e.kind = DeviceEventKind::kAppeared;
    e.info = d;
    hub.on_device_event(e);
  }
  const auto map = hub.serial_to_slot();
  auto slot_of = [&](const std::string& serial) -> std::string {
    for (const auto& [s, slot] : map)
      if (s == serial) return slot;
    return {};
  };

  if (opt.json) {
    nlohmann::json j;
    j["backend"] = spec.backend;
    j["layout"] = settings.layout.name;
    if (library)
      j["leapc"] = {{"library", library->path},
                    {"found_as", library->what},
                    {"version", library->version ? nlohmann::json(leapc_version_text(*library->version))
                                                 : nlohmann::json(nullptr)},
                    {"messages", notices}};
    j["devices"] = nlohmann::json::array();
    for (const auto& d : devices) {
      const std::string slot = slot_of(d.serial);
      j["devices"].push_back(
          {{"serial", d.serial},
           {"backend", d.backend},
           {"model", d.model},
           {"tracking_mode", d.tracking_mode.empty() ? nlohmann::json(nullptr) : nlohmann::json(d.tracking_mode)},
           {"slot", slot.empty() ? nlohmann::json(nullptr) : nlohmann::json(slot)}});
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  if (library) std::cout << leapc_library_text(*library) << "\n";
  for (const auto& n : notices)
    if (n.rfind("LeapC ", 0) != 0) std::cout << "leapc: " << n << "\n";  // the library line is above
  std::cout << devices.size() << " device" << (devices.size() == 1 ? "" : "s") << " on backend " << spec.backend
            << " (layout " << settings.layout.name << ")\n";
  if (devices.empty()) return;
  std::cout << std::left << std::setw(22) << "SERIAL" << std::setw(8) << "SLOT" << std::setw(9) << "BACKEND"
            << std::setw(14) << "MODE"
            << "MODEL\n";
  for (const auto& d : devices) {
    const std::string slot = slot_of(d.serial);
    std::cout << std::left << std::setw(22) << d.serial << std::setw(8) << (slot.empty() ? "-" : slot) << std::setw(9)
              << d.backend << std::setw(14) << (d.tracking_mode.empty() ? "-" : d.tracking_mode) << d.model << "\n";
  }
  if (map.size() < devices.size())
    std::cout << "devices marked '-' have no slot: bind their serials in the layout (Devices tab)\n";
}

void setup_devices(CLI::App& app) {
  auto opt = std::make_shared<DevicesOptions>();
  app.add_option("--backend", opt->backend, "sim, leapc or replay:FILE")->capture_default_str();
  app.add_option("--layout", opt->layout, "Layout file or preset name (slots and bound serials)")
      ->capture_default_str();
  app.add_option("--sim-config", opt->sim_config, "Simulator settings (JSON) for --backend sim");
  app.add_flag("--json", opt->json,
               "Print {backend, layout, leapc{library, found_as, version, messages}, devices[{serial, backend, model, "
               "slot|null}]}");
  app.add_option("--leapc-library", opt->leapc_library,
                 "The LeapC library to load (else LMC_LEAPC_LIBRARY, else where Ultraleap installs it)");
  app.add_option("--wait", opt->wait_s, "leapc: seconds to listen for controllers")->capture_default_str();
  app.callback([opt] { run_devices(*opt); });
}

const lmc::cli::CommandRegistration devices_command{"devices", "List controllers (serial, slot, backend)", 20,
                                                    setup_devices};

}  // namespace
