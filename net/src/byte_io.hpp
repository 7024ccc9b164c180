// byte_io.hpp (internal) — big-endian writer/reader over a buffer whose size the caller has
// already checked; no bounds checks per field. Floats travel as their IEEE-754 bit patterns
// (NaN payloads included), so decode -> encode is bit-exact.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "net/pdu.hpp"

namespace net::detail {

class Writer {
 public:
  explicit Writer(std::uint8_t* p) : p_(p) {}
  void u8(std::uint8_t v) { *p_++ = v; }
  void u16(std::uint16_t v) {
    p_[0] = static_cast<std::uint8_t>(v >> 8);
    p_[1] = static_cast<std::uint8_t>(v);
    p_ += 2;
  }
  void u32(std::uint32_t v) {
    for (int i = 3; i >= 0; --i) *p_++ = static_cast<std::uint8_t>(v >> (8 * i));
  }
  void u64(std::uint64_t v) {
    for (int i = 7; i >= 0; --i) *p_++ = static_cast<std::uint8_t>(v >> (8 * i));
  }
  void f32(float v) { u32(std::bit_cast<std::uint32_t>(v)); }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  template <std::size_t N, class C>
  void bytes(const std::array<C, N>& a) {
    static_assert(sizeof(C) == 1);
    std::memcpy(p_, a.data(), N);
    p_ += N;
  }
  void id(const EntityId& e) { u16(e.site), u16(e.application), u16(e.entity); }
  void id(const EventId& e) { u16(e.site), u16(e.application), u16(e.event_number); }
  void type(const EntityType& t) {
    u8(t.kind), u8(t.domain), u16(t.country), u8(t.category), u8(t.subcategory), u8(t.specific),
        u8(t.extra);
  }
  void vec(const Vec3f& v) { f32(v.x), f32(v.y), f32(v.z); }
  void vec(const Vec3d& v) { f64(v.x), f64(v.y), f64(v.z); }
  void euler(const EulerAnglesF& e) { f32(e.psi), f32(e.theta), f32(e.phi); }
  void descriptor(const MunitionDescriptor& d) {
    type(d.munition_type), u16(d.warhead), u16(d.fuse), u16(d.quantity), u16(d.rate);
  }
  void param(const VariableParameter& v) {
    u8(v.record_type);
    bytes(v.data);
  }
  std::uint8_t* pos() const { return p_; }

 private:
  std::uint8_t* p_;
};

class Reader {
 public:
  explicit Reader(const std::uint8_t* p) : p_(p) {}
  std::uint8_t u8() { return *p_++; }
  std::uint16_t u16() {
    const std::uint16_t v = static_cast<std::uint16_t>((p_[0] << 8) | p_[1]);
    p_ += 2;
    return v;
  }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = (v << 8) | *p_++;
    return v;
  }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v = (v << 8) | *p_++;
    return v;
  }
  float f32() { return std::bit_cast<float>(u32()); }
  double f64() { return std::bit_cast<double>(u64()); }
  template <std::size_t N, class C>
  void bytes(std::array<C, N>& a) {
    static_assert(sizeof(C) == 1);
    std::memcpy(a.data(), p_, N);
    p_ += N;
  }
  void id(EntityId& e) {
    e.site = u16();
    e.application = u16();
    e.entity = u16();
  }
  void id(EventId& e) {
    e.site = u16();
    e.application = u16();
    e.event_number = u16();
  }
  void type(EntityType& t) {
    t.kind = u8();
    t.domain = u8();
    t.country = u16();
    t.category = u8();
    t.subcategory = u8();
    t.specific = u8();
    t.extra = u8();
  }
  void vec(Vec3f& v) {
    v.x = f32();
    v.y = f32();
    v.z = f32();
  }
  void vec(Vec3d& v) {
    v.x = f64();
    v.y = f64();
    v.z = f64();
  }
  void euler(EulerAnglesF& e) {
    e.psi = f32();
    e.theta = f32();
    e.phi = f32();
  }
  void descriptor(MunitionDescriptor& d) {
    type(d.munition_type);
    d.warhead = u16();
    d.fuse = u16();
    d.quantity = u16();
    d.rate = u16();
  }
  void param(VariableParameter& v) {
    v.record_type = u8();
    bytes(v.data);
  }
  const std::uint8_t* pos() const { return p_; }

 private:
  const std::uint8_t* p_;
};

}  // namespace net::detail
