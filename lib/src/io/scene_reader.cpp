// The .scene reader. It works line by line: check the bytes, drop the
// comment, split into tokens, then read one statement. The first problem
// found becomes the one InputError, with the 1-based line and byte column of
// the offending token (or of the end of the line when a token is missing).
#include "orthoray/parse.hpp"

#include "orthoray/grid.hpp"

#include "io/described.hpp"
#include "io/quoted_token.hpp"
#include "io/text_line.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <vector>

namespace orthoray {

InputError::InputError(const std::string& file, int line, int column, const std::string& message)
    : std::runtime_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                         message),
      file_(file), line_(line), column_(column), message_(message) {}

namespace {

using io::Token;

std::string quoted(std::string_view text) {
    return io::quoted_token(text);
}

constexpr const char* number_forms = "a number (integer, fraction like 7/2, or decimal like 0.125)";

class SceneReader {
public:
    SceneReader(std::string_view text, const std::string& file) : text_(text), file_(file) {}

    Scene read() {
        scene_.rays.clear();
        scene_.targets.clear();
        // Rationals are not nothrow-movable, so a growing vector would copy
        // every element on each reallocation: size it once instead.
        scene_.elements.reserve(element_statements());
        const io::TextEnd end = io::for_each_line(
            text_, [&](std::string_view line, int number) { read_line(line, number); });
        eof_line_ = end.line;
        eof_column_ = end.column;
        if (dim_line_ == 0) fail_at_eof("'dim 2' or 'dim 3' as the first statement");
        if (scene_.rays.empty()) fail_at_eof("a 'ray' statement");
        if (scene_.targets.empty()) fail_at_eof("a 'target' statement");
        return std::move(scene_);
    }

private:
    // Lines whose first word names an element kind: an upper bound on the
    // elements the file declares.
    std::size_t element_statements() const {
        std::size_t count = 0;
        for (std::size_t begin = 0; begin < text_.size();) {
            begin = std::min(text_.find_first_not_of(" \t\r", begin), text_.size());
            const std::string_view rest = text_.substr(begin);
            if (rest.starts_with("mirror") || rest.starts_with("absorber") ||
                rest.starts_with("splitter"))
                ++count;
            begin = std::min(text_.find('\n', begin), text_.size()) + 1;
        }
        return count;
    }

    std::string_view text_;
    const std::string& file_;
    Scene scene_;
    int dim_line_ = 0;
    int eof_line_ = 0, eof_column_ = 0;

    // Per-line state while reading one statement.
    std::vector<Token> tokens_;
    std::size_t next_ = 0;
    int line_ = 0, end_column_ = 0;

    [[noreturn]] void fail(int column, const std::string& message) const {
        throw InputError(file_, line_, column, message);
    }
    [[noreturn]] void fail_at_eof(const std::string& expected) const {
        throw InputError(file_, eof_line_, eof_column_, "found end of file, expected " + expected);
    }

    void read_line(std::string_view line, int line_number) {
        line_ = line_number;
        const std::size_t comment = line.find('#');
        if (const std::optional<io::BadByte> bad = io::find_bad_byte(line, comment))
            fail(bad->column, bad->message);
        const std::string_view code = line.substr(0, comment);
        io::split_tokens(code, tokens_);
        next_ = 0;
        end_column_ = static_cast<int>(code.size()) + 1;
        if (!tokens_.empty()) read_statement();
    }

    // `expected` and `what`: a string or a function that builds one
    // (io/described.hpp).
    template <class What>
    const Token& take(const What& expected) {
        if (next_ == tokens_.size())
            fail(end_column_, "found end of line, expected " + io::spelled(expected));
        return tokens_[next_++];
    }

    void expect_end_of_line() {
        if (next_ < tokens_.size())
            fail(tokens_[next_].column,
                 "found " + quoted(tokens_[next_].text) + ", expected end of line");
    }

    template <class What>
    Rational take_number(const What& what) {
        Rational value;
        take_number(value, what);
        return value;
    }
    // The same into `value`, in place (no temporary to allocate and free).
    template <class What>
    void take_number(Rational& value, const What& what) {
        const Token& t = take(what);
        ReadStopCheck::poll();
        const NumberToken::Status status = read_number(t.text, value);
        if (status == NumberToken::Status::zero_denominator)
            fail(t.column, "found " + quoted(t.text) + ", expected " + io::spelled(what) +
                               " with a nonzero denominator");
        if (status != NumberToken::Status::ok)
            fail(t.column, "found " + quoted(t.text) + ", expected " + io::spelled(what) + ": " +
                               number_forms);
    }

    // An axis letter, optionally followed at once by the side the element
    // acts on: 'x', 'x+', 'x-'. Returns false when the token is not one.
    bool axis_of(const Token& t, int& axis, Side& side) const {
        const std::string_view text = t.text;
        if (text.empty() || text.size() > 2 || text[0] < 'x' || text[0] >= 'x' + scene_.dim)
            return false;
        axis = text[0] - 'x';
        side = Side::both;
        if (text.size() == 2) {
            if (text[1] == '+')
                side = Side::plus;
            else if (text[1] == '-')
                side = Side::minus;
            else
                return false;
        }
        return true;
    }

    std::string axis_letters() const { return scene_.dim == 2 ? "x or y" : "x, y or z"; }

    void read_statement() {
        const Token& head = tokens_[next_++];
        if (dim_line_ == 0 && head.text != "dim")
            fail(head.column, "found " + quoted(head.text) +
                                  ", expected 'dim 2' or 'dim 3' as the first statement");
        if (head.text == "dim") return read_dim(head);
        if (head.text == "mirror") return read_element(ElementKind::mirror);
        if (head.text == "absorber") return read_element(ElementKind::absorber);
        if (head.text == "splitter") return read_element(ElementKind::splitter);
        if (head.text == "ray") return read_ray(head.column);
        if (head.text == "target") return read_target();
        fail(head.column,
             "found " + quoted(head.text) +
                 ", expected a statement: dim, mirror, absorber, splitter, ray or target");
    }

    void read_dim(const Token& head) {
        if (dim_line_ != 0)
            fail(head.column, "found a second 'dim' (the first is on line " +
                                  std::to_string(dim_line_) + "), expected one 'dim' statement");
        const Token& t = take("the dimension 2 or 3");
        if (t.text != "2" && t.text != "3")
            fail(t.column, "found " + quoted(t.text) + ", expected the dimension 2 or 3");
        scene_.dim = t.text[0] - '0';
        dim_line_ = line_;
        expect_end_of_line();
    }

    // The element is read in its place in the scene (capacity reserved):
    // building it aside and moving it in cost a dozen allocations more (a
    // rational's move allocates). A bad one ends the read, scene and all.
    void read_element(ElementKind kind) {
        Element& e = scene_.elements.emplace_back();
        e.kind = kind;
        e.line = line_;
        const Token& a = take([&] {
            return "the normal axis (" + axis_letters() + ")" +
                   (scene_.dim == 2 ? " or a diagonal (/ or \\)" : "");
        });
        if (a.text.starts_with('/') || a.text.starts_with('\\')) return read_diagonal(e, a);
        if (!axis_of(a, e.axis, e.side)) {
            // A token that starts like an axis went wrong in its sign.
            const bool signed_axis =
                a.text.size() > 1 && a.text[0] >= 'x' && a.text[0] < 'x' + scene_.dim;
            fail(a.column, "found " + quoted(a.text) + ", expected the normal axis (" +
                               axis_letters() + ") of a " + std::to_string(scene_.dim) + "D scene" +
                               (signed_axis ? ", followed at most by one sign (+ or -)" : ""));
        }
        // 'x +' is a sign parted from its axis: say so rather than call the
        // sign a malformed offset.
        if (next_ < tokens_.size() && (tokens_[next_].text == "+" || tokens_[next_].text == "-"))
            fail(tokens_[next_].column,
                 "found " + quoted(tokens_[next_].text) +
                     " after a space, expected the side's sign right after the axis letter (" +
                     axis_name(e.axis) + std::string(tokens_[next_].text) + ") or the offset");
        const std::string normal(1, axis_name(e.axis));
        take_number(e.lo[e.axis], [&] { return "the offset " + normal + " = c"; });
        e.hi[e.axis] = e.lo[e.axis];
        for (int j = 0; j < scene_.dim; ++j) {
            if (j == e.axis) continue;
            const std::string name(1, axis_name(j));
            const Token& t = take([&] { return "'" + name + "' and its extent"; });
            if (t.text != name)
                fail(t.column, "found " + quoted(t.text) + ", expected '" + name +
                                   "' (the other axes, in the order x, y, z)");
            take_number(e.lo[j], [&] { return "the lower end of the " + name + " extent"; });
            const Token& hi_token = tokens_[next_ < tokens_.size() ? next_ : 0];
            take_number(e.hi[j], [&] { return "the upper end of the " + name + " extent"; });
            if (!(e.lo[j] < e.hi[j]))
                fail(hi_token.column,
                     "found " + quoted(hi_token.text) + " as the upper end of the " + name +
                         " extent, expected a number greater than " + to_string(e.lo[j]));
        }
        read_attenuation(e);
    }

    // `KIND / X0 Y0 X1 Y1` or `KIND \\ X0 Y0 X1 Y1` (docs/octagonal.md): 2D
    // only, two-sided, X0 < X1, and the endpoints on a line of the slope the
    // sign names.
    void read_diagonal(Element& e, const Token& sign) {
        if (scene_.dim != 2)
            fail(sign.column, "found " + quoted(sign.text) +
                                  " in a 3D scene, expected the normal axis (x, y or z): "
                                  "diagonal elements are 2D only");
        if (sign.text.size() != 1)
            fail(sign.column, "found " + quoted(sign.text) + ", expected '/' or '\\' alone" +
                                  (sign.text[1] == '+' || sign.text[1] == '-'
                                       ? ": diagonal elements are two-sided, with no sign"
                                       : ""));
        e.axis = -1;
        e.diagonal = sign.text == "/" ? Diagonal::rising : Diagonal::falling;
        const Rational x0 = take_number("the first endpoint's x");
        const Rational y0 = take_number("the first endpoint's y");
        const Token& x1_token = tokens_[next_ < tokens_.size() ? next_ : 0];
        const Rational x1 = take_number("the second endpoint's x");
        if (!(x0 < x1))
            fail(x1_token.column, "found " + quoted(x1_token.text) +
                                      " as the second endpoint's x, expected a number greater "
                                      "than " +
                                      to_string(x0) + " (the first endpoint's x)");
        const Token& y1_token = tokens_[next_ < tokens_.size() ? next_ : 0];
        const Rational y1 = take_number("the second endpoint's y");
        const Rational wanted =
            e.diagonal == Diagonal::rising ? Rational(y0 + (x1 - x0)) : Rational(y0 - (x1 - x0));
        if (y1 != wanted)
            fail(y1_token.column, "found " + quoted(y1_token.text) +
                                      " as the second endpoint's y, expected " + to_string(wanted) +
                                      " (a segment of slope " +
                                      (e.diagonal == Diagonal::rising ? "+1" : "-1") + ")");
        read_attenuation(e);
        e.lo = {x0, std::min(y0, y1), Rational(0)};
        e.hi = {x1, std::max(y0, y1), Rational(0)};
    }

    // The optional trailing attributes of an element (docs/intensity.md):
    // `reflectance R` on a mirror or splitter, `transmittance T` on a
    // splitter, each at most once, in either order, R and T in [0, 1].
    void read_attenuation(Element& e) {
        int reflectance_column = 0, transmittance_column = 0;
        while (next_ < tokens_.size()) {
            const Token& name = tokens_[next_];
            const bool reflectance = name.text == "reflectance";
            // Any other word is what it always was: something after the end.
            if (!reflectance && name.text != "transmittance") expect_end_of_line();
            if (e.kind == ElementKind::absorber || (!reflectance && e.kind == ElementKind::mirror))
                fail(name.column,
                     "found " + quoted(name.text) + " on " +
                         (e.kind == ElementKind::absorber ? "an absorber" : "a mirror") +
                         ", expected end of line (" +
                         (reflectance ? "an absorber reflects nothing"
                                      : "only a splitter transmits") +
                         ")");
            int& seen = reflectance ? reflectance_column : transmittance_column;
            if (seen != 0)
                fail(name.column, "found a second " + quoted(name.text) +
                                      " (the first is at column " + std::to_string(seen) +
                                      "), expected each attribute once");
            seen = name.column;
            ++next_;
            const std::string what = "the " + std::string(name.text);
            const Token& value_token = tokens_[next_ < tokens_.size() ? next_ : 0];
            Rational value = take_number(what + " (a rational in [0, 1])");
            if (value < 0 || value > 1)
                fail(value_token.column, "found " + quoted(value_token.text) + " as " + what +
                                             ", expected a rational in [0, 1]");
            value.canonicalize();
            (reflectance ? e.reflectance : e.transmittance) = std::move(value);
        }
    }

    // The optional `intensity N` after a ray's direction: a natural number
    // in decimal digits (docs/intensity.md).
    void read_intensity(Ray& ray) {
        if (next_ == tokens_.size()) return;
        const Token& name = tokens_[next_++];
        if (name.text != "intensity") {
            --next_;
            expect_end_of_line();
        }
        const Token& value = take("the intensity (a natural number: 0, 1, 2, ...)");
        if (value.text.find_first_not_of("0123456789") != std::string_view::npos)
            fail(value.column, "found " + quoted(value.text) +
                                   " as the intensity, expected a natural number (0, 1, 2, ...)");
        ReadStopCheck::poll();
        ray.intensity = Integer(std::string(value.text), 10);
        if (next_ < tokens_.size() && tokens_[next_].text == "intensity")
            fail(tokens_[next_].column, "found a second 'intensity' (the first is at column " +
                                            std::to_string(name.column) +
                                            "), expected each attribute once");
        expect_end_of_line();
    }

    // Rays and targets may each appear any number of times; they are
    // numbered from 1 in file order.
    void read_ray(int column) {
        Ray ray;
        ray.line = line_;
        ray.column = column;
        for (int j = 0; j < scene_.dim; ++j)
            ray.start[j] = take_number(std::string("the start ") + axis_name(j));
        int direction_column = next_ < tokens_.size() ? tokens_[next_].column : end_column_;
        bool zero = true;
        for (int j = 0; j < scene_.dim; ++j) {
            ray.direction[j] = take_number(std::string("the direction's ") + axis_name(j));
            zero = zero && ray.direction[j] == 0;
        }
        if (zero) fail(direction_column, "found the direction 0, expected a nonzero direction");
        read_intensity(ray);
        scene_.rays.push_back(std::move(ray));
    }

    void read_target() {
        Vector target;
        for (int j = 0; j < scene_.dim; ++j)
            target[j] = take_number(std::string("the target ") + axis_name(j));
        expect_end_of_line();
        scene_.targets.push_back(std::move(target));
    }
};

} // namespace

Scene read_scene(std::string_view text, const std::string& file) {
    return SceneReader(text, file).read();
}

SceneFormat resolve_scene_format(const std::string& path, SceneFormat requested) {
    if (requested != SceneFormat::automatic) return requested;
    const std::string extension = std::filesystem::path(path).extension().string();
    if (extension == ".json" || extension == ".JSON") return SceneFormat::json;
    if (extension == ".grid" || extension == ".GRID") return SceneFormat::grid;
    return SceneFormat::text;
}

Scene parse_scene(std::string_view text, const std::string& file, SceneFormat format) {
    switch (resolve_scene_format(file, format)) {
    case SceneFormat::json:
        return read_scene_json(text, file);
    case SceneFormat::grid:
        return grid_scene(read_grid_maze(text, file));
    default:
        return read_scene(text, file);
    }
}

Scene load_scene(const std::string& path, SceneFormat format) {
    return parse_scene(read_file(path), path, format);
}

} // namespace orthoray
