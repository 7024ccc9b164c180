// aoi.cpp — the cell grid's group addresses and the held set with hysteresis.
#include "net/aoi.hpp"

#include <arpa/inet.h>

#include <algorithm>

namespace net {

namespace {

constexpr std::uint32_t kScopeNet = 239u << 24;  // 239.0.0.0/8
constexpr std::uint32_t kScopeMask = 0xFF000000u;

std::string dotted(std::uint32_t a) {
  return std::to_string(a >> 24) + "." + std::to_string((a >> 16) & 0xFF) + "." +
         std::to_string((a >> 8) & 0xFF) + "." + std::to_string(a & 0xFF);
}

}  // namespace

Result<AoiGrid, std::string> AoiGrid::make(std::string_view base_group, double cell_m, int max_groups) {
  using R = Result<AoiGrid, std::string>;
  if (!(cell_m > 0) || !std::isfinite(cell_m))
    return R::failure("--aoi " + std::to_string(cell_m) + ": the cell size must be a number of metres above 0");
  if (max_groups < 1 || max_groups > kAoiMaxGroupsLimit)
    return R::failure("--aoi-groups " + std::to_string(max_groups) + ": must be 1.." +
                      std::to_string(kAoiMaxGroupsLimit));
  in_addr a{};
  const std::string text(base_group);
  if (::inet_pton(AF_INET, text.c_str(), &a) != 1)
    return R::failure("AOI base group \"" + text + "\" is not a dotted IPv4 address");
  AoiGrid g;
  g.base_ = ntohl(a.s_addr);
  g.cell_m_ = cell_m;
  int side = 1;
  while ((side + 1) * (side + 1) <= max_groups) ++side;
  g.side_ = side;
  const std::uint32_t last = g.base_ + g.group_count() - 1;
  if ((g.base_ & kScopeMask) != kScopeNet || (last & kScopeMask) != kScopeNet || last < g.base_)
    return R::failure("AOI groups " + dotted(g.base_) + " .. " + dotted(last) + " (" +
                      std::to_string(g.group_count()) +
                      " groups from the --net group) must lie in 239.0.0.0/8: give a --net group "
                      "in 239.0.0.0/8 low enough, or fewer --aoi-groups");
  return g;
}

std::string AoiGrid::address_text(std::uint32_t k) const { return dotted(address(k)); }

std::vector<std::string> AoiGrid::all_groups() const {
  std::vector<std::string> out;
  out.reserve(group_count());
  for (std::uint32_t k = 0; k < group_count(); ++k) out.push_back(address_text(k));
  return out;
}

Result<std::vector<std::string>, std::string> aoi_all_groups(std::string_view base_group, int max_groups) {
  auto g = AoiGrid::make(base_group, 1000.0, max_groups);
  if (!g) return Result<std::vector<std::string>, std::string>::failure(g.error());
  return g.value().all_groups();
}

AoiMembership::AoiMembership(const AoiGrid& grid, double hysteresis_m)
    : grid_(grid),
      hysteresis_m_(std::isfinite(hysteresis_m) && hysteresis_m > 0 ? hysteresis_m : 0.0),
      inner_(grid.group_count(), 0),
      outer_(grid.group_count(), 0),
      held_(grid.group_count(), 0) {}

void AoiMembership::begin() {
  std::fill(inner_.begin(), inner_.end(), 0);
  std::fill(outer_.begin(), outer_.end(), 0);
}

void AoiMembership::want(double x, double y, double radius_m) {
  grid_.for_each_group_near(x, y, radius_m, [&](std::uint32_t k) { inner_[k] = 1; });
  grid_.for_each_group_near(x, y, radius_m + hysteresis_m_, [&](std::uint32_t k) { outer_[k] = 1; });
}

}  // namespace net
