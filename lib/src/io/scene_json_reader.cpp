// The JSON scene reader (docs/scene-json.md). The JSON is parsed into a tree
// that keeps every value's line and column; this file then reads the scene
// out of it, and the first problem becomes the one InputError, at the value
// (or key) at fault.
#include "orthoray/parse.hpp"

#include <algorithm>

#include "io/described.hpp"
#include "io/json_document.hpp"

#include <string>
#include <vector>

namespace orthoray {
namespace {

using io::JsonValue;

constexpr const char* rational_forms =
    "an integer (3 or \"3\") or a rational as a JSON string (\"-7/2\", \"0.125\")";

class SceneJsonReader {
public:
    explicit SceneJsonReader(const std::string& file) : file_(file) {}

    Scene read(const JsonValue& root) {
        expect_type(root, JsonValue::Type::object, "a scene object {\"dim\": ..., ...}");
        check_keys(root, {"dim", "elements", "ray", "rays", "target", "targets"});
        const JsonValue& dim = member(root, "dim", "the dimension 2 or 3");
        if (dim.type != JsonValue::Type::number || (dim.text != "2" && dim.text != "3"))
            fail(dim, "found " + io::describe(dim) + ", expected the dimension 2 or 3");
        scene_.dim = dim.text[0] - '0';

        const JsonValue& elements =
            member(root, "elements", "an array of mirrors, absorbers and splitters");
        expect_type(elements, JsonValue::Type::array,
                    "an array of mirrors, absorbers and splitters");
        scene_.elements.reserve(elements.items.size());
        for (const JsonValue& e : elements.items) read_element(e);

        // One ray as "ray", or several as "rays"; the same for targets.
        scene_.rays.clear();
        for (const JsonValue* ray : one_or_many(root, "ray", "rays", ray_form))
            scene_.rays.push_back(read_ray(*ray));
        scene_.targets.clear();
        for (const JsonValue* target : one_or_many(root, "target", "targets", "a target point"))
            scene_.targets.push_back(point(*target, "the target point"));
        return std::move(scene_);
    }

private:
    static constexpr const char* ray_form = "{\"start\": [...], \"direction\": [...]}";

    // The value of `single`, or the items of `several` (a nonempty array);
    // exactly one of the two keys must be there.
    std::vector<const JsonValue*> one_or_many(const JsonValue& root, std::string_view single,
                                              std::string_view several,
                                              const std::string& what) const {
        const JsonValue* one = root.find(single);
        const JsonValue* many = root.find(several);
        const std::string one_key = io::json_quoted(std::string(single));
        const std::string many_key = io::json_quoted(std::string(several));
        if (one && many)
            fail(*many, "found both " + one_key + " and " + many_key + ", expected one of them");
        if (one) return {one};
        if (!many)
            fail(root, "found an object without " + one_key + ", expected " + one_key + ": " +
                           what + " or " + many_key + ": [...]");
        if (many->type != JsonValue::Type::array || many->items.empty())
            fail(*many, "found " +
                            (many->type == JsonValue::Type::array ? std::string("an empty array")
                                                                  : io::describe(*many)) +
                            ", expected a nonempty array of " + what);
        std::vector<const JsonValue*> items;
        for (const JsonValue& item : many->items) items.push_back(&item);
        return items;
    }

    Ray read_ray(const JsonValue& ray) const {
        expect_type(ray, JsonValue::Type::object, ray_form);
        check_keys(ray, {"start", "direction", "intensity"});
        Ray r;
        r.line = ray.line;
        r.column = ray.column;
        r.start = point(member(ray, "start", "the start point"), "the start point");
        const JsonValue& direction = member(ray, "direction", "the direction");
        r.direction = point(direction, "the direction");
        bool zero = true;
        for (int j = 0; j < scene_.dim; ++j) zero = zero && r.direction[j] == 0;
        if (zero) fail(direction, "found the direction 0, expected a nonzero direction");
        if (const JsonValue* intensity = ray.find("intensity")) r.intensity = natural(*intensity);
        return r;
    }

    // A ray's intensity (docs/intensity.md): a natural number, as a JSON
    // number or a string of decimal digits.
    Integer natural(const JsonValue& value) const {
        const std::string_view text = value.text;
        if ((value.type != JsonValue::Type::number && value.type != JsonValue::Type::string) ||
            text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos)
            fail(value, "found " + io::describe(value) +
                            " as the intensity, expected a natural number (0, 1, 2, ...)");
        ReadStopCheck::poll();
        return Integer(std::string(text), 10);
    }

    // An element's optional "reflectance" and "transmittance"
    // (docs/intensity.md): rationals in [0, 1]; an absorber takes neither, a
    // mirror no transmittance.
    void read_attenuation(const JsonValue& value, Element& e) const {
        for (std::size_t i = 0; i < value.keys.size(); ++i) {
            const bool reflectance = value.keys[i] == "reflectance";
            if (!reflectance && value.keys[i] != "transmittance") continue;
            if (e.kind == ElementKind::absorber || (!reflectance && e.kind == ElementKind::mirror))
                fail(value.key_lines[i], value.key_columns[i],
                     "found the key " + io::json_quoted(value.keys[i]) + " on " +
                         (e.kind == ElementKind::absorber ? "an absorber" : "a mirror") +
                         ", expected it " +
                         (reflectance ? "on a mirror or splitter" : "on a splitter only"));
            const JsonValue& v = *value.find(value.keys[i]);
            const std::string what = "the " + value.keys[i] + " (a rational in [0, 1])";
            Rational r = number(v, what);
            if (r < 0 || r > 1) fail(v, "found " + io::describe(v) + ", expected " + what);
            (reflectance ? e.reflectance : e.transmittance) = std::move(r);
        }
    }

    [[noreturn]] void fail(int line, int column, const std::string& message) const {
        throw InputError(file_, line, column, message);
    }
    [[noreturn]] void fail(const JsonValue& at, const std::string& message) const {
        fail(at.line, at.column, message);
    }

    // `expected` and `what` here: a string or a function that builds one
    // (io/described.hpp).
    template <class What>
    void expect_type(const JsonValue& value, JsonValue::Type type, const What& expected) const {
        if (value.type != type)
            fail(value, "found " + io::describe(value) + ", expected " + io::spelled(expected));
    }

    // Unknown and repeated keys are errors: a misspelt key would otherwise
    // silently change the scene.
    void check_keys(const JsonValue& object,
                    std::initializer_list<std::string_view> allowed) const {
        auto names = [&] {
            std::string list;
            for (std::string_view name : allowed)
                list += (list.empty() ? "\"" : ", \"") + std::string(name) + "\"";
            return list;
        };
        for (std::size_t i = 0; i < object.keys.size(); ++i) {
            const std::string& key = object.keys[i];
            bool known = false;
            for (std::string_view name : allowed) known = known || key == name;
            if (!known)
                fail(object.key_lines[i], object.key_columns[i],
                     "found the key " + io::json_quoted(key) + ", expected one of " + names());
            for (std::size_t k = 0; k < i; ++k)
                if (object.keys[k] == key)
                    fail(object.key_lines[i], object.key_columns[i],
                         "found a second key " + io::json_quoted(key) + " (the first is on line " +
                             std::to_string(object.key_lines[k]) + "), expected each key once");
        }
    }

    template <class What>
    const JsonValue& member(const JsonValue& object, std::string_view key, const What& what) const {
        const JsonValue* value = object.find(key);
        if (!value)
            fail(object, "found an object without \"" + std::string(key) + "\", expected \"" +
                             std::string(key) + "\": " + io::spelled(what));
        return *value;
    }

    // A rational: a JSON string in the .scene number syntax, or a JSON
    // number that is an integer (its literal text is read exactly, never as
    // a double). A JSON number with a fraction or exponent is refused, since
    // JSON tools read those as binary floating point: write it as a string.
    template <class What>
    Rational number(const JsonValue& value, const What& what) const {
        Rational result;
        number(result, value, what);
        return result;
    }
    // The same into `result`, in place (no temporary to allocate and free).
    template <class What>
    void number(Rational& result, const JsonValue& value, const What& what) const {
        if (value.type == JsonValue::Type::number) {
            const std::string_view text = value.text;
            const std::size_t digits = text.starts_with('-') ? 1 : 0;
            if (text.size() > digits &&
                text.find_first_not_of("0123456789", digits) == std::string_view::npos) {
                ReadStopCheck::poll();
                read_number(text, result); // digits with an optional '-': always well formed
                return;
            }
            fail(value, "found the JSON number " + std::string(text) + ", expected " +
                            io::spelled(what) +
                            ": a JSON number only when it is an integer; write " +
                            "fractions and decimals as strings (\"" + std::string(text) +
                            "\") so that no tool rounds them");
        }
        if (value.type != JsonValue::Type::string)
            fail(value, "found " + io::describe(value) + ", expected " + io::spelled(what) + ": " +
                            rational_forms);
        ReadStopCheck::poll();
        const NumberToken::Status status = read_number(value.text, result); // in lowest terms
        if (status == NumberToken::Status::zero_denominator)
            fail(value, "found " + io::describe(value) + ", expected " + io::spelled(what) +
                            " with a nonzero denominator");
        if (status != NumberToken::Status::ok)
            fail(value, "found " + io::describe(value) + ", expected " + io::spelled(what) + ": " +
                            rational_forms);
    }

    // An array of `dim` rationals.
    Vector point(const JsonValue& value, const std::string& what) const {
        const std::string expected = "an array of " + std::to_string(scene_.dim) + " rationals";
        expect_type(value, JsonValue::Type::array, what + " as " + expected);
        if (value.items.size() != static_cast<std::size_t>(scene_.dim))
            fail(value, "found an array of " + std::to_string(value.items.size()) +
                            " values, expected " + what + " as " + expected);
        Vector result;
        for (int j = 0; j < scene_.dim; ++j)
            result[j] = number(value.items[j], what + std::string(" (") + axis_name(j) + ")");
        return result;
    }

    int axis_of(const JsonValue& value) const {
        if (value.type == JsonValue::Type::string && value.text.size() == 1 &&
            value.text[0] >= 'x' && value.text[0] < 'x' + scene_.dim)
            return value.text[0] - 'x';
        const char* letters = scene_.dim == 2 ? "\"x\" or \"y\"" : "\"x\", \"y\" or \"z\"";
        fail(value, "found " + io::describe(value) + ", expected the normal axis " + letters +
                        " of a " + std::to_string(scene_.dim) + "D scene");
    }

    // The element is read in its place in the scene (capacity reserved): a
    // rational's move allocates, so building it aside and moving it in
    // cost a dozen allocations more. A bad one ends the read, scene and all.
    void read_element(const JsonValue& value) {
        expect_type(value, JsonValue::Type::object,
                    "an element {\"kind\": ..., \"axis\": ..., \"offset\": ..., \"extent\": ...}");
        const bool diagonal = value.find("diagonal") != nullptr;
        if (diagonal)
            check_keys(value, {"kind", "diagonal", "from", "to", "reflectance", "transmittance"});
        else
            check_keys(value, {"kind", "axis", "side", "offset", "extent", "reflectance",
                               "transmittance"});
        Element& e = scene_.elements.emplace_back();
        e.line = value.line;
        const char* kinds = "\"mirror\", \"absorber\" or \"splitter\"";
        const JsonValue& kind = member(value, "kind", kinds);
        if (kind.type == JsonValue::Type::string && kind.text == "mirror")
            e.kind = ElementKind::mirror;
        else if (kind.type == JsonValue::Type::string && kind.text == "absorber")
            e.kind = ElementKind::absorber;
        else if (kind.type == JsonValue::Type::string && kind.text == "splitter")
            e.kind = ElementKind::splitter;
        else
            fail(kind, "found " + io::describe(kind) + ", expected " + kinds);
        read_attenuation(value, e);
        if (diagonal) return read_diagonal(value, e);
        // No "side": two-sided. "+" or "-": one-sided (docs/optics.md).
        if (const JsonValue* side = value.find("side")) {
            if (side->type == JsonValue::Type::string && side->text == "+")
                e.side = Side::plus;
            else if (side->type == JsonValue::Type::string && side->text == "-")
                e.side = Side::minus;
            else
                fail(*side, "found " + io::describe(*side) +
                                ", expected the side \"+\" or \"-\" (no \"side\": two-sided)");
        }
        e.axis = axis_of(member(value, "axis", "the normal axis"));
        const std::string normal(1, axis_name(e.axis));
        auto offset_form = [&] { return "the offset " + normal + " = c"; };
        number(e.lo[e.axis], member(value, "offset", offset_form), offset_form);
        e.hi[e.axis] = e.lo[e.axis];

        const JsonValue& extent = member(value, "extent", "the other axes' [lo, hi]");
        expect_type(extent, JsonValue::Type::object,
                    scene_.dim == 2 ? "an object like {\"y\": [\"0\", \"5\"]}"
                                    : "an object like {\"x\": [\"0\", \"4\"], \"y\": "
                                      "[\"0\", \"4\"]}");
        std::string other_axes[2];
        std::size_t count = 0;
        for (int j = 0; j < scene_.dim; ++j)
            if (j != e.axis) other_axes[count++] = std::string(1, axis_name(j));
        if (scene_.dim == 2)
            check_keys(extent, {other_axes[0]});
        else
            check_keys(extent, {other_axes[0], other_axes[1]});
        for (int j = 0; j < scene_.dim; ++j) {
            if (j == e.axis) continue;
            const std::string name(1, axis_name(j));
            const JsonValue& range =
                member(extent, name, [&] { return "the " + name + " extent as [lo, hi]"; });
            if (range.type != JsonValue::Type::array || range.items.size() != 2)
                fail(range, "found " + io::describe(range) +
                                (range.type == JsonValue::Type::array
                                     ? " of " + std::to_string(range.items.size()) + " values"
                                     : "") +
                                ", expected the " + name + " extent as [lo, hi]");
            number(e.lo[j], range.items[0],
                   [&] { return "the lower end of the " + name + " extent"; });
            number(e.hi[j], range.items[1],
                   [&] { return "the upper end of the " + name + " extent"; });
            if (!(e.lo[j] < e.hi[j]))
                fail(range.items[1],
                     "found " + io::describe(range.items[1]) + " as the upper end of the " + name +
                         " extent, expected a number greater than " + to_string(e.lo[j]));
        }
    }

    // {"kind": ..., "diagonal": "/" or "\\", "from": [X0, Y0], "to": [X1, Y1]}
    // (docs/octagonal.md): 2D only, X0 < X1, on a line of the named slope.
    void read_diagonal(const JsonValue& value, Element& e) {
        const JsonValue& sign = *value.find("diagonal");
        if (scene_.dim != 2)
            fail(sign, "found \"diagonal\" in a 3D scene, expected an axis-aligned element "
                       "(\"axis\", \"offset\", \"extent\"): diagonal elements are 2D only");
        if (sign.type == JsonValue::Type::string && sign.text == "/")
            e.diagonal = Diagonal::rising;
        else if (sign.type == JsonValue::Type::string && sign.text == "\\")
            e.diagonal = Diagonal::falling;
        else
            fail(sign, "found " + io::describe(sign) +
                           ", expected the diagonal \"/\" (slope +1) or \"\\\\\" (slope -1)");
        e.axis = -1;
        const Vector a =
            point(member(value, "from", "the first endpoint [X0, Y0]"), "the first endpoint");
        const JsonValue& to = member(value, "to", "the second endpoint [X1, Y1]");
        const Vector b = point(to, "the second endpoint");
        if (!(a[0] < b[0]))
            fail(to.items[0], "found " + io::describe(to.items[0]) +
                                  " as the second endpoint's x, expected a number greater than " +
                                  to_string(a[0]) + " (the first endpoint's x)");
        const Rational wanted = e.diagonal == Diagonal::rising ? Rational(a[1] + (b[0] - a[0]))
                                                               : Rational(a[1] - (b[0] - a[0]));
        if (b[1] != wanted)
            fail(to.items[1], "found " + io::describe(to.items[1]) +
                                  " as the second endpoint's y, expected " + to_string(wanted) +
                                  " (a segment of slope " +
                                  (e.diagonal == Diagonal::rising ? "+1" : "-1") + ")");
        e.lo = {a[0], std::min(a[1], b[1]), Rational(0)};
        e.hi = {b[0], std::max(a[1], b[1]), Rational(0)};
    }

    const std::string& file_;
    Scene scene_;
};

} // namespace

Scene read_scene_json(std::string_view text, const std::string& file) {
    const io::JsonValue root = io::parse_json(text, file);
    return SceneJsonReader(file).read(root);
}

} // namespace orthoray
