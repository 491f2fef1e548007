// ConnectionTable: the HTTP server's open connections, counted per client
// address, and which of them are idle (waiting for a request, or for the
// rest of one whose header has not arrived), longest idle first. It decides
// whether a new connection may open:
//
//   - a client address with max_per_address connections open gets no more
//     (kAddressFull): one address cannot take the whole server;
//   - with max_connections open, the connection idle longest is shed to
//     make room, so idle sockets never lock out a client that has a request
//     to send; only when every open connection is busy (reading a body,
//     awaiting or writing a reply) is the new one refused (kAllBusy).
//
// Invariants: a member is counted under exactly one address; idle members
// are a subset of the members; open() <= max_connections.
// Owns nothing but its bookkeeping: members are the server's connections,
// which remove themselves with Close(). Thread-safety: none; the HTTP
// server's one thread uses it.

#ifndef LOCATOR_SERVER_HTTP_CONNECTION_TABLE_H_
#define LOCATOR_SERVER_HTTP_CONNECTION_TABLE_H_

#include <cstddef>
#include <list>
#include <optional>
#include <string>
#include <unordered_map>

namespace locator {

class ConnectionTable {
 public:
  // A connection the table may shed.
  class Member {
   public:
    // Closes the connection at once; it is no longer in the table then.
    virtual void Shed() = 0;

   protected:
    ~Member() = default;
  };

  enum class Refusal { kNone, kAddressFull, kAllBusy };

  ConnectionTable(size_t max_connections, size_t max_per_address);

  ConnectionTable(const ConnectionTable&) = delete;
  ConnectionTable& operator=(const ConnectionTable&) = delete;

  // Adds `member` (busy), a new connection from `address`, shedding the
  // connection idle longest if all max_connections are open; kNone if it was
  // added, otherwise why not (then it was not).
  Refusal Open(Member* member, const std::string& address);
  // Removes `member`; nothing if it is not in the table (e.g. shed).
  void Close(Member* member);
  // Marks `member` idle (waiting for a request) or busy; nothing if it is
  // not in the table.
  void SetIdle(Member* member, bool idle);

  size_t open() const { return members_.size(); }
  size_t idle() const { return idle_.size(); }
  size_t max_connections() const { return max_connections_; }
  size_t max_per_address() const { return max_per_address_; }

 private:
  struct Entry {
    std::string address;
    // Its place in idle_ while it is idle.
    std::optional<std::list<Member*>::iterator> idle_at;
  };

  const size_t max_connections_;
  const size_t max_per_address_;
  std::unordered_map<Member*, Entry> members_;
  std::unordered_map<std::string, size_t> per_address_;
  std::list<Member*> idle_;  // longest idle first
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_CONNECTION_TABLE_H_
