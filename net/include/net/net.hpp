// net/net.hpp — the whole DIS 7 networking library of the NPSNET node, one include.
//   aoi.hpp            area-of-interest cells -> multicast groups, joins with hysteresis
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
//
// Use in a node's tick loop (t = scenario time in seconds, monotonic):
//   net::SessionConfig cfg;                          // from --net, --iface, --exercise, --site, --app
//   cfg.transport.url = "udp://239.1.2.3:3000";
//   cfg.transport.iface = "127.0.0.1";
//   cfg.exercise_id = 1; cfg.site = 1; cfg.application = 1;
//   net::Session session(cfg);                       // throws std::runtime_error with a message
//   net::RemoteEntityTable remotes;                  // Annex C defaults (12 s timeout, 0.5 s blend)
//   std::vector<net::DrPublisher> pubs(n_local, net::DrPublisher(net::DrAlgorithm::RVW));
//   net::EntityStatePdu es;                          // reused, no allocation per tick
//   each tick:
//     session.poll(net::Overloaded{
//         [&](const net::EntityStatePdu& p) { if (remotes.apply(p, t) == Joined) log_joined(p); },
//         [&](const net::EntityStateUpdatePdu& p) { remotes.apply(p, t); },
//         [&](const net::FirePdu& p) { ... },
//         [&](const net::DetonationPdu& p) { ... crater at p.location ... },
//         [&](const net::CollisionPdu& p) { ... }});
//     remotes.expire(t, [&](const net::RemoteEntity& e) { log_timeout(e); });
//     for (std::size_t i = 0; i < remotes.size(); ++i) draw(remotes[i], remotes.displayed_pose(i, t));
//     for each local vehicle v with true state s (ECEF, DIS Euler):
//       if (pubs[v].needs_update(s, t) != net::DrPublisher::Reason::None) {
//         es.entity_id = session.entity_id(v + 1);
//         es.entity_type = ...; es.marking = net::make_marking(id).value(); es.appearance = ...;
//         net::write_kinematics(s, pubs[v].algorithm(), es);
//         es.header.timestamp = net::relative_timestamp(t);
//         session.send(es);
//         pubs[v].mark_sent(s, t);
//       }
//   session.counters().summary() says what was received, rejected, ignored and sent.
#pragma once

#include "net/aoi.hpp"
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
