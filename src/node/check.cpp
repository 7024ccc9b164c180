// `npsnet check FILE...`: every problem as FILE:LINE: field: message, exit 0 or 2.
#include <cstdio>
#include <fstream>
#include <toml++/toml.h>

#include "node/capture_commands.hpp"
#include "node/entity_type_table.hpp"
#include "node/munition_table.hpp"
#include "node/options.hpp"
#include "node/world_summary.hpp"
#include "world/scenario.hpp"
#include "world/text_file.hpp"

namespace npsnet::node {

namespace {

std::string lower_ext(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  for (auto& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

void check_one(const std::filesystem::path& f, std::vector<world::Problem>& problems, std::string& notes) {
  const std::string fname = f.string();
  if (!world::file_exists(f)) {
    problems.push_back({fname, 0, "file", "file not found"});
    return;
  }
  if (is_capture_file(f)) {  // a recorded exercise: line = frame number
    for (const auto& p : check_capture(f)) problems.push_back({fname, static_cast<int>(p.frame), p.field, p.message});
    return;
  }
  const std::string ext = lower_ext(f);
  try {
    if (ext == ".toml") {
      // A scenario has a [world] table; anything else is a kinds file.
      toml::table t;
      try {
        t = toml::parse_file(fname);
      } catch (const toml::parse_error& e) {
        problems.push_back({fname, static_cast<int>(e.source().begin.line), "syntax", std::string(e.description())});
        return;
      }
      if (t.contains("world") || t.contains("vehicle")) {
        const auto sc = world::load_scenario(f);
        const auto w = world::build_world(sc);
        const std::string crs = raster_crs_name(sc.terrain);
        if (const std::string warn = origin_warning(sc, w, crs); !warn.empty()) notes += warn + "\n";
        notes += fname + ": world\n" + world_summary(sc, w, crs);
      } else if (t.contains("entity")) {  // models/entity_types.toml
        const auto table = EntityTypeTable::load(f);
        world::ModelLibrary models;
        const auto ps = table.check_kinds(world::KindTable::load(world::default_kinds_file(), models));
        problems.insert(problems.end(), ps.begin(), ps.end());
      } else if (t.contains("warhead") || t.contains("munition")) {  // models/munitions.toml
        const auto table = MunitionTable::load(f);
        world::ModelLibrary models;
        const auto ps = table.check_kinds(world::KindTable::load(world::default_kinds_file(), models));
        problems.insert(problems.end(), ps.begin(), ps.end());
      } else {
        world::ModelLibrary models;
        (void)world::KindTable::load(f, models);
      }
    } else if (ext == ".csv") {
      // Objects against the bundled kinds; map checks need a terrain, which a scenario gives.
      world::ModelLibrary models;
      const auto kinds = world::KindTable::load(world::default_kinds_file(), models);
      world::Terrain big(2, 2, 1e9, {0, 0, 0, 0}, {});
      world::FixedObjects objs;
      world::load_objects_csv(f, kinds, big, -1e18, objs, problems);
    } else if (ext == ".obj") {
      (void)world::load_obj(f);
    } else {
      (void)world::Terrain::load(f, {});
    }
  } catch (const world::InputError& e) {
    problems.insert(problems.end(), e.problems().begin(), e.problems().end());
  }
}

}  // namespace

int check_command(const std::vector<std::string>& files) {
  std::vector<world::Problem> problems;
  std::string notes;
  for (const auto& f : files) check_one(f, problems, notes);
  for (const auto& p : problems) std::printf("%s\n", p.str().c_str());
  if (problems.empty()) std::printf("%s", notes.c_str());
  if (problems.empty()) std::printf("ok: %zu file(s)\n", files.size());
  return problems.empty() ? 0 : 2;
}

}  // namespace npsnet::node
