#include "tendril/nn/feature_heads.hpp"

#include <map>
#include <mutex>
#include <optional>

#include "tendril/core/dynamics_layer.hpp"
#include "tendril/core/error.hpp"
#include "tendril/nn/mlp_head.hpp"

namespace tendril::nn {

namespace {

struct KindTable {
  std::mutex mutex;
  std::map<std::string, FeatureHeadKind> kinds{
      {MlpHead::kKind, FeatureHeadKind{&MlpHead::create, &MlpHead::read}}};
};

KindTable& table() {
  static KindTable instance;
  return instance;
}

const char* const kKnownKinds = "mlp, lk_encoder or lk_full";

std::optional<FeatureHeadKind> installed_kind(const std::string& kind) {
  std::lock_guard lock(table().mutex);
  const auto found = table().kinds.find(kind);
  if (found == table().kinds.end()) return std::nullopt;
  return found->second;
}

FeatureHeadKind kind_named(const std::string& kind, const std::string& where) {
  if (std::optional<FeatureHeadKind> found = installed_kind(kind)) return *found;
  const bool learned_model = kind == "lk_encoder" || kind == "lk_full";
  // A program that loads the dynamics layer on demand loads it now; it installs these kinds.
  if (learned_model && load_dynamics_layer()) {
    if (std::optional<FeatureHeadKind> found = installed_kind(kind)) return *found;
  }
  if (learned_model) {
    throw Error("the policy head '" + kind +
                    "' needs the dynamics layer, which this program was built without",
                where);
  }
  throw Error("unknown policy head '" + kind + "' (expected " + kKnownKinds + ")", where);
}

}  // namespace

FeatureHeadSpec FeatureHeadSpec::from_config(const Config& head) {
  FeatureHeadSpec spec;
  spec.kind = head.get<std::string>("kind");
  if (spec.kind != "mlp" && !spec.uses_model()) {
    throw Error("unknown policy head '" + spec.kind + "' (expected " + kKnownKinds + ")",
                head.where("kind"));
  }
  spec.trainable = head.get_or<bool>("trainable", spec.trainable);
  if (spec.uses_model()) {
    spec.model = head.get<std::string>("model");
    spec.pretrained = head.get_or<bool>("pretrained", spec.pretrained);
  } else {
    spec.layers = head.get_or<std::vector<int64_t>>("layers", spec.layers);
    spec.inputs = head.get<int64_t>("inputs");
    require(!spec.layers.empty(), "needs at least the output size", head.where("layers"));
    for (int64_t size : spec.layers) {
      require(size >= 1 && size <= 65536, "layer sizes must be in [1, 65536]",
              head.where("layers"));
    }
    require(spec.inputs >= 1, "must be positive", head.where("inputs"));
  }
  // A key of the other kind (layers for lk_encoder, model for mlp) is left unread and refused.
  head.reject_unknown();
  return spec;
}

void install_feature_head_kind(const std::string& kind, FeatureHeadKind builder) {
  require(builder.create && builder.read, "a head kind needs both a maker and a reader",
          "nn::install_feature_head_kind");
  std::lock_guard lock(table().mutex);
  table().kinds[kind] = std::move(builder);
}

CreatedHead create_feature_head(const FeatureHeadSpec& spec, Rng& rng) {
  CreatedHead created = kind_named(spec.kind, "algo.head.kind").create(spec, rng);
  require(created.head != nullptr && created.parameters.size() == created.head->parameter_count(),
          "the '" + spec.kind + "' head came without its weights", "algo.head");
  return created;
}

std::shared_ptr<const FeatureHead> read_feature_head(const ArchiveReader& reader,
                                                     const std::string& prefix) {
  const std::string kind = reader.get_string(prefix + "_kind");
  std::shared_ptr<const FeatureHead> head = kind_named(kind, reader.name()).read(reader, prefix);
  require(head != nullptr && head->kind() == kind, "the '" + kind + "' head could not be read",
          reader.name());
  return head;
}

void write_feature_head(ArchiveWriter& writer, const std::string& prefix, const FeatureHead& head) {
  writer.put(prefix + "_kind", head.kind());
  head.write(writer, prefix);
}

}  // namespace tendril::nn
