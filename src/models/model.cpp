#include "bounce/models/model.hpp"

namespace bounce::models {

Engine engine_of(const NormalInteraction& normal) {
  switch (normal.index()) {
    case 0: return Engine::force_law;
    case 1: return Engine::adhesive;
    default: return Engine::crack;
  }
}

const NormalForceModel* Model::force_law() const {
  const auto* f = std::get_if<ForceLaw>(&normal);
  return f ? f->force.get() : nullptr;
}

const KrijtParameters* Model::contact_parameters() const {
  if (const auto* a = std::get_if<AdhesiveContact>(&normal)) return &a->parameters;
  if (const auto* c = std::get_if<CrackContact>(&normal)) return &c->parameters;
  return nullptr;
}

}  // namespace bounce::models
