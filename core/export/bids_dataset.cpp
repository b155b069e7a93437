// Placeholder until the BIDS writer lands: the API is fixed so the Review tab can be built against it.
#include "core/export/bids_dataset.h"

#include "core/common/error.h"

namespace lmc {

BidsExportReport export_bids(const BidsExportRequest&) { throw Error("BIDS export is not available in this build"); }

}  // namespace lmc
