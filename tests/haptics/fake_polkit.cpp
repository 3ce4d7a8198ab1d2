// A stand-in for PolicyKit on the private bus of rtkit_check.sh: rtkit-daemon asks
// org.freedesktop.PolicyKit1 whether a client may have real-time priority, and on a desktop
// polkitd says yes for the active local session. This answers every CheckAuthorization with
// "authorized" (the test is about our client's request, not about the machine's policy).
// Runs until killed.
#include <dbus/dbus.h>

#include <cstdio>
#include <cstring>

namespace {

void answer(DBusConnection* bus, DBusMessage* call) {
  DBusMessage* reply = dbus_message_new_method_return(call);
  DBusMessageIter it, result, details;
  dbus_message_iter_init_append(reply, &it);
  dbus_message_iter_open_container(&it, DBUS_TYPE_STRUCT, nullptr, &result);
  dbus_bool_t authorized = TRUE, challenge = FALSE;
  dbus_message_iter_append_basic(&result, DBUS_TYPE_BOOLEAN, &authorized);
  dbus_message_iter_append_basic(&result, DBUS_TYPE_BOOLEAN, &challenge);
  dbus_message_iter_open_container(&result, DBUS_TYPE_ARRAY, "{ss}", &details);
  dbus_message_iter_close_container(&result, &details);
  dbus_message_iter_close_container(&it, &result);
  dbus_connection_send(bus, reply, nullptr);
  dbus_message_unref(reply);
}

}  // namespace

int main() {
  DBusError err;
  dbus_error_init(&err);
  DBusConnection* bus = dbus_bus_get(DBUS_BUS_SYSTEM, &err);
  if (bus == nullptr) {
    std::fprintf(stderr, "fake_polkit: no bus: %s\n", err.message);
    return 1;
  }
  if (dbus_bus_request_name(bus, "org.freedesktop.PolicyKit1", 0, &err) != DBUS_REQUEST_NAME_REPLY_PRIMARY_OWNER) {
    std::fprintf(stderr, "fake_polkit: cannot own the name\n");
    return 1;
  }
  while (dbus_connection_read_write(bus, -1)) {
    while (DBusMessage* m = dbus_connection_pop_message(bus)) {
      if (dbus_message_is_method_call(m, "org.freedesktop.PolicyKit1.Authority", "CheckAuthorization")) answer(bus, m);
      dbus_message_unref(m);
    }
  }
  return 0;
}
