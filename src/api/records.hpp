#pragma once
// Private: Records that several commands of the front door add to their results.

#include "bounce/api/front_door.hpp"

namespace bounce::api::detail {

/// A material's values (SI); its name under `name_key` ("name" in the table, "material" in a body).
Record material_record(const Material& m, const char* name_key = "name");
/// kappa, g* and the Hertz scales of a Hertz-type model (BP04 §8.3); nothing for the others.
void add_scales(Record& out, const Pair& pair, const models::Model& model, double velocity);
/// The closed forms beside a collision (analysis/closed_forms.hpp).
Record closed_forms_record(const Pair& pair, const models::Model& model, double velocity);
/// Sticking grains as one body (analysis::merged_body).
Record merged_record(const Pair& pair, double velocity);
/// The contact time of a bounce; null for sticking grains, which stay in contact (the time
/// integrated is `integrated_time`).
Value contact_time_value(const dynamics::CollisionOutcome& o);
/// The maximum overlap; null where sticking was certain before it.
Value max_overlap_value(const dynamics::CollisionOutcome& o);

}  // namespace bounce::api::detail
