// net/net.hpp — the whole DIS 7 networking library of the NPSNET node, one include.
//   pdu.hpp            wire structs of Entity State, Fire, Detonation, Collision, ES Update
//   codec.hpp          encode / decode one PDU, byte-exact; DecodeError reasons
//   datagram.hpp       walk several PDUs in a datagram (filtering, counting); pack a datagram
//   counters.hpp       receive/send counters with a printable summary
//   timestamp.hpp      DIS relative / absolute timestamps
//   marking.hpp        11-character ASCII markings
//   transport.hpp      UDP multicast / unicast / broadcast endpoint (Asio), non-blocking
//   session.hpp        transport + identity + parser + counters: what a node holds
//   dead_reckoning.hpp DR algorithms 1-5 (and 6-9 approximated), send-threshold policy
//   remote_table.hpp   remote entities: dead-reckoned, smoothed, timed out
#pragma once

#include "net/codec.hpp"
#include "net/counters.hpp"
#include "net/datagram.hpp"
#include "net/dead_reckoning.hpp"
#include "net/marking.hpp"
#include "net/pdu.hpp"
#include "net/remote_table.hpp"
#include "net/result.hpp"
#include "net/session.hpp"
#include "net/timestamp.hpp"
#include "net/transport.hpp"
