#include "andros/link/fault_link.hpp"

namespace andros::link {
namespace {

const std::string kDownText = "held down by the event script";
const std::string kTakenText = "taken by another program (event script)";
const std::string kStalledText = "stalled: the server reads nothing (event script)";

}  // namespace

SendResult FaultLink::send(const protocol::Frame& frame, std::int64_t now_ns) {
  if (fault_ != Fault::kNone) {
    ++down_;
    return SendResult::kDown;
  }
  return inner_.send(frame, now_ns);
}

const std::string& FaultLink::detail() const {
  switch (fault_) {
    case Fault::kDown: return kDownText;
    case Fault::kTaken: return kTakenText;
    case Fault::kNone: break;
  }
  return stalled_ ? kStalledText : inner_.detail();
}

const LinkCounters& FaultLink::counters() const {
  merged_ = inner_.counters();
  merged_.down += down_;
  return merged_;
}

SendResult SinkLink::send(const protocol::Frame& frame, std::int64_t now_ns) {
  state_ = LinkState::kUp;
  detail_.clear();
  deliver_(now_ns, frame);
  ++counters_.sent;
  return SendResult::kSent;
}

bool SinkLink::drain_and_close(int /*timeout_ms*/) {
  state_ = LinkState::kConnecting;
  detail_ = kClosedDetail;
  return true;
}

}  // namespace andros::link
