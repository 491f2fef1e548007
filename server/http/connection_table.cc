#include "server/http/connection_table.h"

namespace locator {

ConnectionTable::ConnectionTable(size_t max_connections, size_t max_per_address)
    : max_connections_(max_connections), max_per_address_(max_per_address) {}

ConnectionTable::Refusal ConnectionTable::Open(Member* member,
                                               const std::string& address) {
  const auto counted = per_address_.find(address);
  if (counted != per_address_.end() && counted->second >= max_per_address_) {
    return Refusal::kAddressFull;
  }
  if (members_.size() >= max_connections_) {
    if (idle_.empty()) return Refusal::kAllBusy;
    Member* shed = idle_.front();
    Close(shed);
    shed->Shed();
  }
  members_.emplace(member, Entry{.address = address, .idle_at = std::nullopt});
  ++per_address_[address];
  return Refusal::kNone;
}

void ConnectionTable::Close(Member* member) {
  const auto found = members_.find(member);
  if (found == members_.end()) return;
  if (found->second.idle_at.has_value()) idle_.erase(*found->second.idle_at);
  const auto counted = per_address_.find(found->second.address);
  if (--counted->second == 0) per_address_.erase(counted);
  members_.erase(found);
}

void ConnectionTable::SetIdle(Member* member, bool idle) {
  const auto found = members_.find(member);
  if (found == members_.end()) return;
  std::optional<std::list<Member*>::iterator>& idle_at = found->second.idle_at;
  if (idle && !idle_at.has_value()) {
    idle_at = idle_.insert(idle_.end(), member);
  } else if (!idle && idle_at.has_value()) {
    idle_.erase(*idle_at);
    idle_at.reset();
  }
}

}  // namespace locator
