// bench_espdu.cpp — Entity State PDU encode + decode throughput (items/s = ESPDUs per second).
// BM_EspduEncodeDecode: one encode into a fixed buffer and one decode into a reused struct per
// item, no variable parameters. BM_EspduEncodeDecode4Parts: the same with 4 articulated parts.
// BM_DatagramParse: a 1400-octet datagram of 9 ESPDUs through DatagramParser (items = PDUs).
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>

#include "net/net.hpp"

namespace {

net::EntityStatePdu sample(std::size_t parts) {
  net::EntityStatePdu p;
  p.header.timestamp = net::relative_timestamp(1234.5);
  p.entity_id = {1, 2, 3};
  p.force_id = 1;
  p.entity_type = {1, 1, 225, 1, 1, 3, 0};
  p.linear_velocity = {10.5f, -3.25f, 0.5f};
  p.location = {-2707522.25, -4353260.5, 3781450.75};
  p.orientation = {1.0f, 0.1f, -0.05f};
  p.appearance = 0x00010000;
  p.dead_reckoning.algorithm = 4;
  p.marking = net::make_marking("tank1").value();
  for (std::size_t i = 0; i < parts; ++i) {
    net::VariableParameter v;
    v.record_type = 0;
    v.data[0] = static_cast<std::uint8_t>(i);
    p.variable_parameters.push_back(v);
  }
  return p;
}

void run(benchmark::State& state, std::size_t parts) {
  const net::EntityStatePdu in = sample(parts);
  net::EntityStatePdu out;
  std::array<std::uint8_t, net::kMaxPduSize> buf{};
  for (auto _ : state) {
    auto n = net::encode(in, std::span<std::uint8_t>(buf));
    benchmark::DoNotOptimize(buf.data());
    auto e = net::decode(std::span<const std::uint8_t>(buf.data(), n.value()), out);
    benchmark::DoNotOptimize(e);
    benchmark::DoNotOptimize(out.location.x);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(net::encoded_size(in)));
}

void BM_EspduEncodeDecode(benchmark::State& state) { run(state, 0); }
void BM_EspduEncodeDecode4Parts(benchmark::State& state) { run(state, 4); }

void BM_DatagramParse(benchmark::State& state) {
  net::DatagramBuilder builder(1400);
  auto p = sample(0);
  while (builder.add(p)) ++p.entity_id.entity;
  net::DatagramParser parser;
  net::Counters counters;
  double sum = 0;
  for (auto _ : state) {
    parser.parse(builder.bytes(), counters,
                 [&](const net::EntityStatePdu& es) { sum += es.location.x; });
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(builder.pdu_count()));
}

BENCHMARK(BM_EspduEncodeDecode);
BENCHMARK(BM_EspduEncodeDecode4Parts);
BENCHMARK(BM_DatagramParse);

}  // namespace

BENCHMARK_MAIN();
