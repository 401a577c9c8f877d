#pragma once
// One unit's result as a shard stores it (units/<index>.json) and the merge reads it back: every field of
// the BenchRun, exactly (doubles round-trip), with the unit's key and how long the whole unit took.

#include "physltl/campaign/campaign.h"

#include <nlohmann/json.hpp>

#include <string>

namespace physltl::campaign {

struct UnitRecord {
  size_t index = 0;      // canonical position in the campaign
  std::string key;       // Unit::key
  double elapsed_s = 0;  // the whole unit: planning, replay, improving
  BenchRun run;
};

nlohmann::ordered_json to_json(const UnitRecord& record);
// Throws BadInput naming `source` when a field is missing or of the wrong type.
UnitRecord unit_record_from_json(const nlohmann::json& json, const std::string& source);

}  // namespace physltl::campaign
