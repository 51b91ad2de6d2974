#include "andros/link/vehicle_view.hpp"

namespace andros::link {

void VehicleView::push(std::span<const std::uint8_t> bytes, std::int64_t now_ns) {
  decoder_.push(bytes, [&](const protocol::DecodedFrame& f) {
    timing_.add(now_ns);
    last_ = f.data;
    last_valid_ = f.valid;
    last_errors_ = f.errors;
    if (observer_) observer_(f, now_ns);
  });
}

VehicleStatus VehicleView::status(std::int64_t now_ns) const {
  return VehicleStatus{last_, last_valid_, last_errors_, decoder_.stats(), timing_.summary(now_ns)};
}

}  // namespace andros::link
