// Placeholder translation unit so lmc_devices links before any source is added.
namespace lmc::devices {
int devices_layer_version() { return 1; }
}  // namespace lmc::devices
