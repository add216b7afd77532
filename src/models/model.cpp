#include "bounce/models/model.hpp"

namespace bounce::models {

Engine engine_of(const NormalInteraction& normal) {
  return std::visit([](const auto& kind) { return engine_of<std::decay_t<decltype(kind)>>(); }, normal);
}

const NormalForceModel* Model::force_law() const {
  const auto* f = std::get_if<ForceLaw>(&normal);
  return f ? f->force.get() : nullptr;
}

const AdhesivePair* Model::contact_parameters() const {
  if (const auto* a = std::get_if<AdhesiveContact>(&normal)) return &a->parameters;
  if (const auto* c = std::get_if<CrackContact>(&normal)) return &c->parameters;
  return nullptr;
}

const KrijtParameters* Model::crack_parameters() const {
  const auto* c = std::get_if<CrackContact>(&normal);
  return c ? &c->parameters : nullptr;
}

}  // namespace bounce::models
