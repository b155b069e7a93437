// Keeps lmc_ui_model non-empty while ui/model and ui/scene grow.
namespace lmc::ui {
int ui_model_version() {
  return 1;
}
}  // namespace lmc::ui
