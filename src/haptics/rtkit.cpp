#include "haptics/rtkit.h"

#include <dbus/dbus.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>

namespace ps::rtkit {

namespace {

constexpr const char* kName = "org.freedesktop.RealtimeKit1";
constexpr const char* kPath = "/org/freedesktop/RealtimeKit1";
constexpr int kTimeoutMs = 1000;

struct BusError {
  DBusError e;
  BusError() { dbus_error_init(&e); }
  ~BusError() { dbus_error_free(&e); }
  std::string text() const { return dbus_error_is_set(&e) ? std::string(e.message) : std::string("no reply"); }
};

using Message = std::unique_ptr<DBusMessage, decltype(&dbus_message_unref)>;
using Connection = std::unique_ptr<DBusConnection, decltype(&dbus_connection_unref)>;

Message call(DBusConnection* bus, DBusMessage* m, BusError& err) {
  Message reply(dbus_connection_send_with_reply_and_block(bus, m, kTimeoutMs, &err.e), &dbus_message_unref);
  dbus_message_unref(m);
  return reply;
}

// The daemon's MaxRealtimePriority property.
Result<int> max_priority(DBusConnection* bus) {
  DBusMessage* m = dbus_message_new_method_call(kName, kPath, "org.freedesktop.DBus.Properties", "Get");
  const char* iface = kName;
  const char* prop = "MaxRealtimePriority";
  dbus_message_append_args(m, DBUS_TYPE_STRING, &iface, DBUS_TYPE_STRING, &prop, DBUS_TYPE_INVALID);
  BusError err;
  Message reply = call(bus, m, err);
  if (!reply) return make_error("RealtimeKit is not available: " + err.text());
  DBusMessageIter it, variant;
  dbus_message_iter_init(reply.get(), &it);
  if (dbus_message_iter_get_arg_type(&it) != DBUS_TYPE_VARIANT) return make_error("RealtimeKit: unexpected reply");
  dbus_message_iter_recurse(&it, &variant);
  if (dbus_message_iter_get_arg_type(&variant) != DBUS_TYPE_INT32) return make_error("RealtimeKit: unexpected reply");
  dbus_int32_t value = 0;
  dbus_message_iter_get_basic(&variant, &value);
  return static_cast<int>(value);
}

}  // namespace

Result<int> make_thread_realtime(pid_t tid, int priority) {
  BusError err;
  Connection bus(dbus_bus_get_private(DBUS_BUS_SYSTEM, &err.e), &dbus_connection_unref);
  if (!bus) return make_error("RealtimeKit is not available: no system bus (" + err.text() + ")");
  dbus_connection_set_exit_on_disconnect(bus.get(), false);
  struct Closer {
    DBusConnection* c;
    ~Closer() { dbus_connection_close(c); }
  } closer{bus.get()};
  Result<int> max = max_priority(bus.get());
  if (!max) return max;
  const int granted = std::clamp(priority, 1, std::max(1, max.value()));
  rlimit limit{static_cast<rlim_t>(kRtTimeUsec), static_cast<rlim_t>(kRtTimeUsec)};
  if (setrlimit(RLIMIT_RTTIME, &limit) != 0) return make_error("RealtimeKit: cannot set RLIMIT_RTTIME");
  DBusMessage* m = dbus_message_new_method_call(kName, kPath, kName, "MakeThreadRealtime");
  dbus_uint64_t thread = static_cast<dbus_uint64_t>(tid);
  dbus_uint32_t prio = static_cast<dbus_uint32_t>(granted);
  dbus_message_append_args(m, DBUS_TYPE_UINT64, &thread, DBUS_TYPE_UINT32, &prio, DBUS_TYPE_INVALID);
  Message reply = call(bus.get(), m, err);
  if (!reply) return make_error("RealtimeKit refused: " + err.text());
  return granted;
}

}  // namespace ps::rtkit
