#include "core/modelling/operation_list.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "core/io/json_text.h"
#include "core/support/quoted_text.h"
#include "core/mesh/covariance_mesh.h"
#include "core/support/error.h"
#include "core/modelling/affine_transform.h"
#include "core/modelling/bevel.h"
#include "core/modelling/bisect.h"
#include "core/modelling/bridge.h"
#include "core/modelling/crease_edges.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/duplicate.h"
#include "core/modelling/edge_operations.h"
#include "core/modelling/extrude.h"
#include "core/modelling/fill.h"
#include "core/modelling/grid_fill.h"
#include "core/modelling/inset.h"
#include "core/modelling/knife.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/mirror.h"
#include "core/modelling/primitives.h"
#include "core/modelling/slide.h"
#include "core/modelling/spin.h"
#include "core/modelling/split_faces.h"
#include "core/modelling/subdivide_mesh.h"
#include "core/plans/planned_surface.h"
#include "core/reference/subdivision_size.h"

namespace gps {
namespace {

using Json = nlohmann::json;
using Run = std::function<Modelled(const CovarianceMesh&)>;
// An operation that changes Gaussians or sharpness only: on the mesh itself, returning the selection
// and setting the summary.
using InPlace = std::function<std::vector<int>(CovarianceMesh&, std::string&)>;
using Edges = std::vector<std::array<int, 2>>;

// Element `i` of the JSON list `list` (named `key`) as a vertex, edge or face index.
int index_at(const Json& list, size_t i, const std::string& key) {
  try {
    return int(json_integer(list[i], 0, INT32_MAX));
  } catch (const Error& e) {
    throw usage_error("\"" + key + "\"[" + std::to_string(i) + "] " + e.what());
  }
}

// The keys of one operation object, read with checks; every message names the key.
class Fields {
public:
  explicit Fields(const Json& object) : object_(object) {}

  bool has(const char* key) {
    used_.insert(key);
    return object_.contains(key);
  }
  bool is_text(const char* key) { return has(key) && object_.at(key).is_string(); }
  bool is_list(const char* key) { return has(key) && object_.at(key).is_array(); }
  /// Any number of finite numbers (the caller checks the count).
  std::vector<double> list_of_numbers(const char* key) { return numbers(key, at(key).size()); }
  double number(const char* key) {
    const Json& v = at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw usage_error("\"" + std::string(key) + "\" must be a finite number");
    return v.get<double>();
  }
  double number(const char* key, double otherwise) { return has(key) ? number(key) : otherwise; }
  // A crease's or corner's sharpness: 0 or more, as the file formats take it.
  double sharpness(const char* key) {
    const double s = number(key);
    if (s < 0) throw usage_error("\"" + std::string(key) + "\" must be 0 or more, got " + json_shown(at(key)));
    return s;
  }
  int integer(const char* key, int lo, int hi) {
    const Json& v = at(key);
    try {
      return int(json_integer(v, lo, hi));
    } catch (const Error& e) {
      throw usage_error("\"" + std::string(key) + "\" " + e.what());
    }
  }
  int integer(const char* key, int lo, int hi, int otherwise) { return has(key) ? integer(key, lo, hi) : otherwise; }
  bool boolean(const char* key) {
    const Json& v = at(key);
    if (!v.is_boolean()) throw usage_error("\"" + std::string(key) + "\" must be true or false");
    return v.get<bool>();
  }
  std::string text(const char* key) {
    const Json& v = at(key);
    if (!v.is_string()) throw usage_error("\"" + std::string(key) + "\" must be a string");
    return v.get<std::string>();
  }
  std::vector<int> indices(const char* key) { return index_list(at(key), key); }
  std::array<int, 2> edge(const char* key) { return edge_of(at(key), key); }
  Edges edges(const char* key) {
    const Json& v = at(key);
    if (!v.is_array() || v.empty()) throw usage_error("\"" + std::string(key) + "\" must be a list of [a, b] edges");
    Edges out;
    for (const Json& e : v) out.push_back(edge_of(e, key));
    return out;
  }
  std::vector<double> numbers(const char* key, size_t count) {
    const Json& v = at(key);
    const std::string what = "\"" + std::string(key) + "\" must be " + std::to_string(count) + " numbers";
    if (!v.is_array() || v.size() != count) throw usage_error(what);
    std::vector<double> out;
    for (const Json& x : v) {
      if (!x.is_number() || !std::isfinite(x.get<double>())) throw usage_error(what);
      out.push_back(x.get<double>());
    }
    return out;
  }
  Vec3 vector3(const char* key) {
    const std::vector<double> v = numbers(key, 3);
    return Vec3(v[0], v[1], v[2]);
  }
  /// The value of a key as it is, for a nested object.
  const Json& json(const char* key) { return at(key); }
  /// Refuses keys the operation does not read (a misspelt key would otherwise be ignored).
  void check_all_used() const {
    for (const auto& [key, value] : object_.items())
      if (key != "op" && !used_.count(key)) throw usage_error("unknown key " + quoted_token(key));
  }

private:
  const Json& at(const char* key) {
    used_.insert(key);
    if (!object_.contains(key)) throw usage_error("\"" + std::string(key) + "\" is missing");
    return object_.at(key);
  }
  static std::vector<int> index_list(const Json& v, const std::string& key) {
    if (!v.is_array()) throw usage_error("\"" + key + "\" must be a list of indices");
    std::vector<int> out;
    for (size_t i = 0; i < v.size(); ++i) out.push_back(index_at(v, i, key));
    return out;
  }
  static std::array<int, 2> edge_of(const Json& v, const std::string& key) {
    const std::vector<int> e = index_list(v, key);
    if (e.size() != 2) throw usage_error("\"" + key + "\" must give an edge as [a, b]");
    return {e[0], e[1]};
  }

  const Json& object_;
  std::set<std::string> used_;
};

// Exactly one of the keys present: which one.
const char* one_of(Fields& f, std::initializer_list<const char*> keys) {
  const char* found = nullptr;
  std::string names;
  for (const char* k : keys) {
    names += std::string(names.empty() ? "" : " or ") + "\"" + k + "\"";
    if (f.has(k)) {
      if (found) throw usage_error("give one of " + names);
      found = k;
    }
  }
  if (!found) throw usage_error("give " + names);
  return found;
}

// A 3×3 covariance from its six entries xx xy xz yy yz zz.
Mat3 covariance_of(const std::vector<double>& c) {
  Mat3 m;
  m << c[0], c[1], c[2], c[1], c[3], c[4], c[2], c[4], c[5];
  return m;
}

// {"op":"set","vertices":[…],"mean":[x,y,z],"covariance":[xx,xy,xz,yy,yz,zz],"scale":s}: Gaussians set
// directly (the mean, the covariance, then the covariance scaled).
InPlace set_gaussians(Fields& f) {
  const std::vector<int> vertices = f.indices("vertices");
  std::optional<Vec3> mean;
  std::shared_ptr<const Mat3> covariance;  // held apart: a list of a million scales holds no room for one
  double scale = 1;
  if (f.has("mean")) mean = f.vector3("mean");
  if (f.has("covariance")) covariance = std::make_shared<const Mat3>(covariance_of(f.numbers("covariance", 6)));
  if (f.has("scale") && !((scale = f.number("scale")) > 0)) throw usage_error("\"scale\" must be positive");
  if (!mean && !covariance && !f.has("scale")) throw usage_error("give \"mean\", \"covariance\" or \"scale\"");
  return [=](CovarianceMesh& mesh, std::string& summary) {
    const std::vector<int> set = sorted_vertices(mesh.n_vertices(), vertices);
    std::vector<Mat3> covariances(set.size());
    for (size_t i = 0; i < set.size(); ++i) {
      const int v = set[i];
      covariances[i] = (covariance ? *covariance : mesh.covariances[size_t(v)]) * scale;
      std::string why = mean ? position_problem(*mean) : "";
      if (why.empty()) why = covariance_problem(covariances[i]);
      if (!why.empty())
        throw Error("vertex " + std::to_string(v) + " would have " + (why.rfind("has ", 0) == 0 ? why.substr(4) : why));
    }
    for (size_t i = 0; i < set.size(); ++i) {
      if (mean) mesh.set_mean(size_t(set[i]), *mean);
      mesh.covariances[size_t(set[i])] = covariances[i];
    }
    summary = "set " + std::to_string(set.size()) + (set.size() == 1 ? " Gaussian" : " Gaussians");
    return set;
  };
}

InPlace transform(Fields& f) {
  std::vector<int> vertices;  // empty: all
  if (!f.has("vertices")) throw usage_error("\"vertices\" is missing (a list of indices, or \"all\")");
  if (!f.is_text("vertices") || f.text("vertices") != "all") {
    vertices = f.indices("vertices");
    if (vertices.empty()) throw usage_error("\"vertices\" must be \"all\" or a non-empty list of indices");
  }
  const std::vector<double> rows =
      f.has("matrix") && f.is_list("matrix") ? f.list_of_numbers("matrix") : f.numbers("matrix", 16);
  const AffineMap map = [&] {
    try {
      return AffineMap::from_rows(rows);
    } catch (const Error& e) {
      throw usage_error(e.what());
    }
  }();
  return [=](CovarianceMesh& mesh, std::string& summary) {
    return transform_vertices_in_place(mesh, vertices, map, summary);
  };
}

// {"op":"bevel","edges":[[a,b],…] or "vertices":[…],"width":w}, optional "segments", "profile",
// "clamp", "width_type" and (edges) "crease".
Run bevel(Fields& f) {
  const bool on_edges = std::string(one_of(f, {"edges", "vertices"})) == "edges";
  BevelOptions o;
  if (!((o.width = f.number("width")) > 0)) throw usage_error("\"width\" must be positive");
  o.segments = f.integer("segments", 1, kMaxBevelSegments, 1);
  if (!((o.profile = f.number("profile", 0.5)) > 0 && o.profile <= 1))
    throw usage_error("\"profile\" must be a number in (0, 1]");
  if (f.has("clamp")) o.clamp = f.boolean("clamp");
  if (f.has("width_type") && !bevel_width_named(f.text("width_type"), o.width_type))
    throw usage_error("\"width_type\" must be \"offset\", \"width\", \"depth\" or \"percent\"");
  if (!on_edges) {
    const std::vector<int> vertices = f.indices("vertices");
    if (vertices.empty()) throw usage_error("\"vertices\" is empty");
    return [=](const CovarianceMesh& m) { return bevel_vertices(m, vertices, o); };
  }
  const Edges edges = f.edges("edges");
  if (!((o.crease = f.number("crease", 0)) >= 0)) throw usage_error("\"crease\" must be a sharpness (a number ≥ 0)");
  return [=](const CovarianceMesh& m) { return bevel_edges(m, edges, o); };
}

// {"op":"bisect","plane":{"point":[x,y,z],"normal":[x,y,z]}}: every face the plane crosses cut along it.
Run bisect_step(Fields& f) {
  const Json& object = f.json("plane");
  if (!object.is_object()) throw usage_error("\"plane\" must be {\"point\": [x, y, z], \"normal\": [x, y, z]}");
  Fields plane(object);
  try {
    const Vec3 point = plane.vector3("point"), normal = plane.vector3("normal");
    plane.check_all_used();
    if (!(normal.norm() > 0)) throw usage_error("\"normal\" must not be zero");
    return [=](const CovarianceMesh& m) { return bisect(m, point, normal); };
  } catch (const Error& e) {
    throw usage_error("\"plane\": " + std::string(e.what()));
  }
}

// {"op":"duplicate","faces":[…]|"all","offset":[x,y,z]}: a moved copy of the faces as a new part.
Run duplicate_step(Fields& f) {
  const Vec3 offset = f.has("offset") ? f.vector3("offset") : Vec3::Zero();
  if (f.is_text("faces")) {
    if (f.text("faces") != "all") throw usage_error("\"faces\" must be \"all\" or a non-empty list of indices");
    return [=](const CovarianceMesh& m) {
      std::vector<int> all(m.n_faces());
      for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
      return duplicate_faces(m, all, offset);
    };
  }
  const std::vector<int> faces = f.indices("faces");
  if (faces.empty()) throw usage_error("\"faces\" must be \"all\" or a non-empty list of indices");
  return [=](const CovarianceMesh& m) { return duplicate_faces(m, faces, offset); };
}

// {"op":"spin","vertices":[…],"axis":[x,y,z],"center":[x,y,z],"angle":deg,"steps":n}: a lathe.
Run spin_step(Fields& f) {
  const std::vector<int> vertices = f.indices("vertices");
  if (vertices.size() < 2) throw usage_error("\"vertices\" must be a chain of at least 2 vertices");
  const Vec3 axis = f.vector3("axis");
  if (!(axis.norm() > 0)) throw usage_error("\"axis\" must not be zero");
  const Vec3 center = f.has("center") ? f.vector3("center") : Vec3::Zero();
  const double angle = f.number("angle");
  if (angle == 0 || std::abs(angle) > 360) throw usage_error("\"angle\" must be from -360 to 360 degrees and not 0");
  const int steps = f.integer("steps", std::abs(angle) == 360 ? 3 : 1, 1000);
  return [=](const CovarianceMesh& m) { return spin(m, vertices, axis, center, angle, steps); };
}

// {"op":"mirror","axis":"x"|"y"|"z","center":[x,y,z],"merge":true}: the mesh and its mirror image.
Run mirror_step(Fields& f) {
  const std::string name = f.text("axis");
  const std::map<std::string, int> axes{{"x", 0}, {"y", 1}, {"z", 2}};
  if (!axes.count(name)) throw usage_error("\"axis\" must be \"x\", \"y\" or \"z\"");
  const int axis = axes.at(name);
  const Vec3 center = f.has("center") ? f.vector3("center") : Vec3::Zero();
  const bool merge = !f.has("merge") || f.boolean("merge");
  return [=](const CovarianceMesh& m) { return mirror(m, axis, center, merge); };
}

// {"op":"knife","points":[[x,y,z],…]}: the mesh cut along the path through points on its faces.
Run knife_step(Fields& f) {
  const Json& list = f.json("points");
  if (!list.is_array() || list.size() < 2)
    throw usage_error("\"points\" must be a list of at least 2 [x, y, z] points");
  std::vector<Vec3> points;
  for (size_t i = 0; i < list.size(); ++i) {
    const Json& p = list[i];
    const auto finite = [](const Json& x) { return x.is_number() && std::isfinite(x.get<double>()); };
    if (!p.is_array() || p.size() != 3 || !std::all_of(p.begin(), p.end(), finite))
      throw usage_error("\"points\"[" + std::to_string(i) + "] must be 3 numbers");
    points.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  }
  return [=](const CovarianceMesh& m) { return knife(m, points); };
}

using Append = std::function<std::vector<int>(MeshArrays&, std::string&)>;

// An operation's step: a function of the mesh, or `append` (an addition) or `in_place` set instead.
Run parse_step(const std::string& op, Fields& f, Append& append, InPlace& in_place) {
  if (op == "subdivide") {
    if (f.has("faces")) {
      const std::vector<int> faces = f.indices("faces");
      if (faces.empty()) throw usage_error("\"faces\" is empty");
      return [=](const CovarianceMesh& m) { return subdivide_faces(m, faces); };
    }
    return [](const CovarianceMesh& m) { return subdivide_all(m); };
  }
  if (op == "loop_cut") {
    const auto e = f.edge("edge");
    const int cuts = f.integer("cuts", 1, 64, 1);
    const double slide = f.number("slide", 0);
    return [=](const CovarianceMesh& m) { return loop_cut(m, e[0], e[1], cuts, slide); };
  }
  if (op == "split_edge") {
    const auto e = f.edge("edge");
    const double t = f.number("t", 0.5);
    if (!(t > 0 && t < 1))
      throw usage_error("\"t\" must be between 0 and 1 (not either), got " + json_shown(f.json("t")));
    return [=](const CovarianceMesh& m) { return split_edge(m, e[0], e[1], t); };
  }
  if (op == "slide") {
    const double factor = f.number("factor");
    if (std::string(one_of(f, {"edges", "vertex"})) == "edges") {
      const Edges edges = f.edges("edges");
      const bool even = f.has("even") && f.boolean("even");
      return [=](const CovarianceMesh& m) { return edge_slide(m, edges, factor, even); };
    }
    const int vertex = f.integer("vertex", 0, INT32_MAX);
    const int toward = f.integer("toward", 0, INT32_MAX);
    return [=](const CovarianceMesh& m) { return vertex_slide(m, vertex, toward, factor); };
  }
  if (op == "flip_edge") {
    const auto e = f.edge("edge");
    return [=](const CovarianceMesh& m) { return flip_edge(m, e[0], e[1]); };
  }
  if (op == "extrude") {
    const char* what = one_of(f, {"faces", "edges", "vertices"});
    // An extrusion by nothing would lay its new faces on the old ones (Blender leaves such doubles).
    if (std::string(what) == "faces") {
      const std::vector<int> faces = f.indices("faces");
      const double distance = f.number("distance");
      if (distance == 0) throw usage_error("\"distance\" must not be 0 (the new faces would lie on the old ones)");
      append = [=](MeshArrays& a, std::string& summary) { return extrude_faces_in(a, faces, distance, summary); };
      return nullptr;
    }
    const Vec3 offset = f.vector3("offset");
    if (offset.isZero(0)) throw usage_error("\"offset\" must not be [0, 0, 0] (the new faces would have no area)");
    if (std::string(what) == "edges") {
      const Edges edges = f.edges("edges");
      return [=](const CovarianceMesh& m) { return extrude_edges(m, edges, offset); };
    }
    const std::vector<int> vertices = f.indices("vertices");
    return [=](const CovarianceMesh& m) { return extrude_vertices(m, vertices, offset); };
  }
  if (op == "bevel") return bevel(f);
  if (op == "inset") {
    const std::vector<int> faces = f.indices("faces");
    const double thickness = f.number("thickness");
    if (!(thickness > 0)) throw usage_error("\"thickness\" must be positive, got " + json_shown(f.json("thickness")));
    append = [=](MeshArrays& a, std::string& summary) { return inset_faces_in(a, faces, thickness, summary); };
    return nullptr;
  }
  if (op == "delete") {
    const char* what = one_of(f, {"faces", "edges", "vertices"});
    if (std::string(what) == "edges") {
      const Edges edges = f.edges("edges");
      append = [=](MeshArrays& a, std::string& summary) { return delete_edges_in(a, edges, summary); };
    } else {
      const std::vector<int> list = f.indices(what);
      append = [=, faces = std::string(what) == "faces"](MeshArrays& a, std::string& summary) {
        return faces ? delete_faces_in(a, list, summary) : delete_vertices_in(a, list, summary);
      };
    }
    return nullptr;
  }
  if (op == "dissolve") {
    const char* what = one_of(f, {"edges", "vertices"});
    if (std::string(what) == "edges") {
      const Edges edges = f.edges("edges");
      return [=](const CovarianceMesh& m) { return dissolve_edges(m, edges); };
    }
    const std::vector<int> list = f.indices(what);
    return [=](const CovarianceMesh& m) { return dissolve_vertices(m, list); };
  }
  if (op == "merge") {
    const std::vector<int> vertices = f.indices("vertices");
    const std::string at = f.has("at") ? f.text("at") : "center";
    const std::map<std::string, MergePoint> points{
        {"center", MergePoint::center}, {"first", MergePoint::first}, {"last", MergePoint::last}};
    if (!points.count(at)) throw usage_error("\"at\" must be \"center\", \"first\" or \"last\"");
    const MergePoint point = points.at(at);
    return [=](const CovarianceMesh& m) { return merge_vertices(m, vertices, point); };
  }
  if (op == "weld") {
    const double distance = f.number("distance");
    if (!(distance > 0)) throw usage_error("\"distance\" must be positive, got " + json_shown(f.json("distance")));
    const std::vector<int> vertices = f.has("vertices") ? f.indices("vertices") : std::vector<int>();
    return [=](const CovarianceMesh& m) { return weld_by_distance(m, vertices, distance); };
  }
  if (op == "fill") {
    const std::vector<int> vertices = f.indices("vertices");
    return [=](const CovarianceMesh& m) { return fill(m, vertices); };
  }
  if (op == "grid_fill") {
    const std::vector<int> vertices = f.indices("vertices");
    const int span = f.integer("span", 1, INT32_MAX, 0);
    const int offset = f.integer("offset", INT32_MIN + 1, INT32_MAX, 0);
    return [=](const CovarianceMesh& m) { return grid_fill(m, vertices, span, offset); };
  }
  if (op == "split") {
    const std::vector<int> faces = f.indices("faces");
    if (faces.empty()) throw usage_error("\"faces\" is empty");
    return [=](const CovarianceMesh& m) { return split_faces(m, faces); };
  }
  if (op == "transform") {
    in_place = transform(f);
    return nullptr;
  }
  if (op == "add") {
    const std::string name = f.text("primitive");
    const std::optional<Primitive> primitive = primitive_named(name);
    if (!primitive) {
      std::string names;
      for (const std::string& n : primitive_names()) names += (names.empty() ? "" : ", ") + n;
      throw usage_error("unknown primitive " + quoted_token(name) + " (known: " + names + ")");
    }
    const Vec3 center = f.has("center") ? f.vector3("center") : Vec3::Zero();
    const double size = f.number("size", 1.0);
    if (!(size > 0)) throw usage_error("\"size\" must be positive");
    append = [=](MeshArrays& a, std::string& summary) {
      return append_primitive(a, *primitive, center, size, summary);
    };
    return nullptr;
  }
  if (op == "set") {
    in_place = set_gaussians(f);
    return nullptr;
  }
  if (op == "crease") {
    if (f.is_text("edges")) {
      if (f.text("edges") != "sharp") throw usage_error("\"edges\" must be \"sharp\" or a list of [a, b] edges");
      const double angle = f.number("angle");
      if (!(angle >= 0 && angle < 180)) throw usage_error("\"angle\" must be from 0 to less than 180 degrees");
      const double sharpness = f.sharpness("sharpness");
      return [=](const CovarianceMesh& m) { return crease_sharp_edges(m, angle, sharpness); };
    }
    const Edges edges = f.edges("edges");
    const double sharpness = f.sharpness("sharpness");
    in_place = [=](CovarianceMesh& m, std::string& summary) {
      return set_crease_in_place(m, edges, sharpness, summary);
    };
    return nullptr;
  }
  if (op == "bisect") return bisect_step(f);
  if (op == "knife") return knife_step(f);
  if (op == "duplicate") return duplicate_step(f);
  if (op == "spin") return spin_step(f);
  if (op == "mirror") return mirror_step(f);
  if (op == "corner") {
    const std::vector<int> vertices = f.indices("vertices");
    if (vertices.empty()) throw usage_error("\"vertices\" is empty");
    const double sharpness = f.sharpness("sharpness");
    in_place = [=](CovarianceMesh& m, std::string& summary) {
      return set_corner_in_place(m, vertices, sharpness, summary);
    };
    return nullptr;
  }
  std::string names;
  for (const std::string& n : operation_names()) names += (names.empty() ? "" : ", ") + n;
  throw usage_error("unknown operation (known: " + names + ")");
}

// The operation names, made once.
const std::vector<std::string>& known_names() {
  static const std::vector<std::string> names = operation_names();
  return names;
}

// An operation's name as messages show it: a known one as it is, any other quoted and cut.
std::string shown_name(const std::string& name) {
  const std::vector<std::string>& known = known_names();
  return std::find(known.begin(), known.end(), name) != known.end() ? name : quoted_token(name);
}

// A known operation's name as a view of known_names(), which a list's steps hold for the program's life.
std::string_view lasting_name(const std::string& name) {
  const std::vector<std::string>& known = known_names();
  const auto at = std::find(known.begin(), known.end(), name);
  return at == known.end() ? std::string_view("?") : std::string_view(*at);
}

// "SOURCE: message", or the message alone for an unnamed source.
std::string prefixed(const std::string& source, const std::string& message) {
  return source.empty() ? message : source + ": " + message;
}

}  // namespace

std::vector<std::string> operation_names() {
  return {"subdivide", "loop_cut", "split_edge", "flip_edge", "extrude", "inset",  "delete", "dissolve", "merge",
          "weld",      "fill",     "bridge",     "transform", "add",     "set",    "crease", "corner",   "slide",
          "bevel",     "bisect",   "knife",      "duplicate", "spin",    "mirror", "split",  "grid_fill"};
}

OperationList OperationList::parse(const std::string& text, const std::string& source) {
  OperationList list;
  list.source_ = source;
  // Op by op as the text is read: a long list is never held whole as JSON.
  const bool array = parse_json_array(text, source, "ops", [&](size_t i, Json&& object) {
    const std::string where = prefixed(source, "ops[" + std::to_string(i) + "]");
    if (!object.is_object() || !object.contains("op") || !object["op"].is_string())
      throw usage_error(where + ": expected an object with \"op\"");
    const std::string name = object["op"].get<std::string>();
    try {
      Fields fields(object);
      Run run;
      Append append;
      InPlace in_place;
      if (name == "bridge" && fields.has("faces")) {
        if (fields.has("loops")) throw usage_error("give one of \"loops\" or \"faces\"");
        const std::vector<int> faces = fields.indices("faces");
        if (faces.empty()) throw usage_error("\"faces\" is empty");
        run = [faces](const CovarianceMesh& m) { return bridge_faces(m, faces); };
      } else if (name == "bridge") {
        if (!fields.has("loops"))
          throw usage_error("\"loops\" is missing (two lists of boundary vertices, or \"faces\")");
        const Json& loops = object["loops"];
        if (!loops.is_array() || loops.size() != 2) throw usage_error("\"loops\" must be two lists of vertices");
        std::array<std::vector<int>, 2> l;
        for (size_t k = 0; k < 2; ++k) {
          if (!loops[k].is_array()) throw usage_error("\"loops\" must be two lists of vertices");
          for (size_t i = 0; i < loops[k].size(); ++i)
            l[k].push_back(index_at(loops[k], i, "loops[" + std::to_string(k) + "]"));
        }
        run = [l](const CovarianceMesh& m) { return bridge(m, l[0], l[1]); };
      } else {
        run = parse_step(name, fields, append, in_place);
      }
      fields.check_all_used();
      const bool whole = name == "subdivide" && !object.contains("faces");
      const std::string_view kept = lasting_name(name);
      if (append)
        list.steps_.push_back({kept, std::move(append), whole});
      else if (in_place)
        list.steps_.push_back({kept, std::move(in_place), whole});
      else
        list.steps_.push_back({kept, std::move(run), whole});
    } catch (const Error& e) {
      throw Error(where + " (" + shown_name(name) + "): " + e.what(), e.kind());
    }
  });
  if (!array) throw usage_error(prefixed(source, "expected a JSON array of operations [{\"op\": ...}, ...]"));
  return list;
}

std::vector<std::string> OperationList::names() const {
  std::vector<std::string> out;
  for (const Step& s : steps_) out.emplace_back(s.name);
  return out;
}

Modelled OperationList::apply(const CovarianceMesh& mesh, std::vector<std::string>* summaries) const {
  // Each step's result is made in place (a mesh has no move, so an assignment would copy it); a run of
  // steps made on arrays (additions, deletions, extrusions and insets of faces) changes the arrays and
  // builds the mesh once after its last; a step on Gaussians or sharpness changes the list's own copy of
  // the mesh where it stands.
  std::unique_ptr<Modelled> current;
  std::optional<MeshArrays> arrays;
  const auto mesh_now = [&]() -> const CovarianceMesh& { return current ? current->mesh : mesh; };
  for (size_t i = 0; i < steps_.size(); ++i) {
    const Step& step = steps_[i];
    try {
      if (step.subdivides_whole_mesh && (i == 0 || !steps_[i - 1].subdivides_whole_mesh))
        check_subdivisions(i, mesh_now());
      if (const AppendStep* append = step.append()) {
        if (!arrays) arrays = arrays_of(mesh_now());
        std::string summary;
        std::vector<int> selection = (*append)(*arrays, summary);
        if (summaries) summaries->push_back(summary);
        if (i + 1 < steps_.size() && steps_[i + 1].append()) continue;
        auto made =
            std::make_unique<Modelled>(modelled(mesh_now(), std::move(*arrays), std::move(selection), std::move(summary)));
        check_new_geometry(mesh_now(), *made);
        current = std::move(made);
        arrays.reset();
        continue;
      }
      if (const InPlaceStep* in_place = step.in_place()) {
        if (!current) current.reset(new Modelled{mesh, {}, "", {}, {}});  // the list's one copy of its input
        current->selection = (*in_place)(current->mesh, current->summary);
      } else {
        auto made = std::make_unique<Modelled>(std::get<MakeStep>(step.action)(mesh_now()));
        check_new_geometry(mesh_now(), *made);
        current = std::move(made);
      }
    } catch (const Error& e) {
      throw Error(prefixed(source_, "ops[" + std::to_string(i) + "] (" + std::string(step.name) + "): " + e.what()),
                  e.kind());  // a step's name is a known one
    }
    if (summaries) summaries->push_back(current->summary);
  }
  if (!current) return {mesh, {}, "", {}, {}};
  return std::move(*current);
}

void OperationList::check_subdivisions(size_t first, const CovarianceMesh& mesh) const {
  size_t last = first;
  while (last + 1 < steps_.size() && steps_[last + 1].subdivides_whole_mesh) ++last;
  SubdivisionOptions options;
  options.scheme = scheme_for(mesh.topology(), PlanOptions{});
  options.levels = int(std::min<size_t>(last - first + 1, 1000));
  // The last level's peak, with the mesh before it held.
  OutputSize size = subdivision_size(mesh, options);
  --options.levels;
  size.bytes += subdivision_size(mesh, options).bytes;
  const std::string count = std::to_string(last - first + 1);
  check_output_size(
      size,
      count + " whole-mesh subdivisions (ops[" + std::to_string(first) + "] to ops[" + std::to_string(last) + "])",
      "faces", "use fewer subdivisions");
}

}  // namespace gps
