#pragma once

#include <string>
#include <utility>

namespace tabletop {

/// What holds an entity up: the table, the ground, another entity, or
/// nothing. A value, compared by kind and name; named only at output.
/// "table", "ground" and "none" are reserved, so no entity carries them.
class Support {
 public:
  enum class Kind { None, Table, Ground, Entity };

  Support() = default;
  static Support table() { return Support(Kind::Table, {}); }
  static Support ground() { return Support(Kind::Ground, {}); }
  static Support entity(std::string name) { return Support(Kind::Entity, std::move(name)); }
  /// The support a name in a scenario or an output means: "table",
  /// "ground", "none" or "" (nothing), else an entity.
  static Support named(const std::string& name) {
    if (name == "table") return table();
    if (name == "ground") return ground();
    if (name.empty() || name == "none") return {};
    return entity(name);
  }

  Kind kind() const { return kind_; }
  bool isNone() const { return kind_ == Kind::None; }
  bool isEntity() const { return kind_ == Kind::Entity; }
  /// The entity's name when kind() is Entity, else empty.
  const std::string& entityName() const { return entity_; }
  /// The output name: "table", "ground", "none" or the entity's name.
  std::string name() const {
    switch (kind_) {
      case Kind::Table: return "table";
      case Kind::Ground: return "ground";
      case Kind::Entity: return entity_;
      case Kind::None: break;
    }
    return "none";
  }

  bool operator==(const Support& o) const { return kind_ == o.kind_ && entity_ == o.entity_; }
  bool operator!=(const Support& o) const { return !(*this == o); }
  bool operator<(const Support& o) const { return kind_ != o.kind_ ? kind_ < o.kind_ : entity_ < o.entity_; }

 private:
  Support(Kind kind, std::string entity) : kind_(kind), entity_(std::move(entity)) {}
  Kind kind_ = Kind::None;
  std::string entity_;
};

}  // namespace tabletop
