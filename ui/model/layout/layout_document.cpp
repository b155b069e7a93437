#include "ui/model/layout/layout_document.h"

#include <utility>

namespace lmc::ui {

LayoutDocument make_document(Layout layout) {
  LayoutDocument doc;
  doc.layout = std::move(layout);
  doc.sync_locks();
  return doc;
}

}  // namespace lmc::ui
