// The certificate tokenizer for both formats; see certificate_reader.hpp.
#include "certify/certificate_reader.hpp"

#include "io/json_document.hpp"
#include "io/quoted_token.hpp"
#include "orthoray/parse.hpp"

#include <algorithm>
#include <climits>

namespace orthoray::certify {
namespace {

int clamp_int(long long value) {
    return value > INT_MAX ? INT_MAX : static_cast<int>(value);
}

// The statements a JSON line may hold, in the order they are read: a line
// can hold several (the header holds the version and dim, the verdict holds
// answer, reason, reflections and the reason's own values), and the order
// of keys inside the object does not matter.
// The induction statements (docs/induction-certificates.md) and the
// illumination statements (branch, lit, step, unlit, unknown) come one a line.
constexpr std::string_view json_keywords[] = {"orthoray-certificate",
                                              "dim",
                                              "illumination",
                                              "min-intensity",
                                              "branch",
                                              "lit",
                                              "unlit",
                                              "unknown",
                                              "point",
                                              "method",
                                              "scale",
                                              "modulus",
                                              "transversal",
                                              "lifted",
                                              "first",
                                              "twin",
                                              "twin-search",
                                              "walk-search",
                                              "piece",
                                              "step",
                                              "answer",
                                              "reason",
                                              "reflections",
                                              "target",
                                              "direction",
                                              "state",
                                              "period",
                                              "tail",
                                              "states",
                                              "partial",
                                              "end"};

// A statement whose JSON value is an object: its keys, in the order their
// values become operands. A `labelled` key also becomes a token itself, as
// the text format writes that word before the value (`branch X V ray R
// reflections K`), so both formats give the same statement.
struct ObjectPart {
    std::string_view key;
    bool labelled;
};
struct ObjectForm {
    std::string_view keyword;
    std::vector<ObjectPart> parts;
};

const std::vector<ObjectForm>& object_forms() {
    static const std::vector<ObjectForm> forms = {
        {"state", {{"point", false}, {"direction", false}}},
        {"step", {{"point", false}, {"direction", false}}},
        {"branch",
         {{"point", false},
          {"direction", false},
          {"ray", true},
          {"reflections", true},
          {"intensity", true}}},
        {"lit", {{"target", false}, {"reflections", true}, {"ray", true}, {"intensity", true}}},
    };
    return forms;
}

const ObjectForm* object_form(std::string_view keyword) {
    for (const ObjectForm& form : object_forms())
        if (form.keyword == keyword) return &form;
    return nullptr;
}

// A JSON value as an operand token: scalars by their text, containers by a
// placeholder that no operand check accepts.
using Token = CertificateReader::Token;

Token operand(const io::JsonValue& v) {
    switch (v.type) {
    case io::JsonValue::Type::array:
        return {"[...]", v.column};
    case io::JsonValue::Type::object:
        return {"{...}", v.column};
    default:
        return {v.text, v.column};
    }
}

// The operands of an object value, in the order of its form; a key the
// form does not name, or named twice, is bad input. A missing key leaves
// its operands out, so the statement's own check reports what is missing.
void object_operands(const io::JsonValue& value, const ObjectForm& form, const std::string& name,
                     int line, std::vector<Token>& tokens) {
    std::string known;
    for (std::size_t i = 0; i < form.parts.size(); ++i)
        known += std::string(i == 0                       ? "\""
                             : i + 1 == form.parts.size() ? " or \""
                                                          : ", \"") +
                 std::string(form.parts[i].key) + "\"";
    for (std::size_t k = 0; k < value.keys.size(); ++k) {
        bool named = false;
        for (const ObjectPart& part : form.parts) named = named || value.keys[k] == part.key;
        if (!named)
            throw InputError(name, line, value.key_columns[k],
                             "found the key " + io::json_quoted(value.keys[k]) + ", expected " +
                                 known);
        for (std::size_t j = 0; j < k; ++j)
            if (value.keys[j] == value.keys[k])
                throw InputError(name, line, value.key_columns[k],
                                 "found a second key " + io::json_quoted(value.keys[k]) +
                                     ", expected each key once");
    }
    for (const ObjectPart& part : form.parts) {
        for (std::size_t k = 0; k < value.keys.size(); ++k) {
            if (value.keys[k] != part.key) continue;
            if (part.labelled) tokens.push_back({std::string(part.key), value.key_columns[k]});
            const io::JsonValue& item = value.items[k];
            if (item.type == io::JsonValue::Type::array)
                for (const io::JsonValue& x : item.items) tokens.push_back(operand(x));
            else
                tokens.push_back(operand(item));
        }
    }
}

} // namespace

CertificateReader::CertificateReader(std::istream& in, const std::string& name)
    : in_(in), name_(name) {}

// Like std::getline, but a line longer than input_cap_bytes is bad input:
// the file is streamed so that memory does not grow with it, and one endless
// line (/dev/zero) must not undo that.
bool CertificateReader::read_line() {
    line_.clear();
    char chunk[1 << 12];
    bool any = false;
    while (true) {
        in_.getline(chunk, sizeof chunk);
        const std::size_t n = static_cast<std::size_t>(in_.gcount());
        any = any || n > 0;
        const bool full = in_.fail() && !in_.eof() && n == sizeof chunk - 1;
        line_.append(chunk, full ? n : n - (in_.good() && n > 0 ? 1 : 0));
        if (line_.size() > input_cap_bytes)
            throw InputError(name_, clamp_int(line_number_ + 1),
                             clamp_int(static_cast<long long>(input_cap_bytes) + 1),
                             "found more than " + std::to_string(input_cap_bytes >> 20) +
                                 " MiB in one line, expected lines of at most that size "
                                 "(docs/limits.md)");
        if (!full) break;
        in_.clear(); // the chunk filled up: the line goes on
    }
    if (!any && !in_.good()) return false;
    ++line_number_;
    if (!line_.empty() && line_.back() == '\r') line_.pop_back(); // CRLF
    return true;
}

bool CertificateReader::next() {
    if (!pending_.empty()) {
        statement_ = std::move(pending_.front());
        pending_.pop_front();
        return true;
    }
    while (read_line()) {
        if (!format_known_) {
            const std::size_t first = line_.find_first_not_of(" \t");
            if (first == std::string::npos) continue;
            format_ = line_[first] == '{' ? CertificateFormat::jsonl : CertificateFormat::text;
            format_known_ = true;
        }
        if (format_ == CertificateFormat::text) {
            split_text();
            if (!statement_.tokens.empty()) return true;
        } else if (line_.find_first_not_of(" \t") != std::string::npos) {
            split_json();
            return true;
        }
    }
    return false;
}

void CertificateReader::advance() {
    if (!next()) throw IncompleteCertificate{};
}

// Tokens are separated by spaces or tabs; '#' starts a comment.
void CertificateReader::split_text() {
    statement_.tokens.clear();
    statement_.line = line_number_;
    std::string_view text(line_);
    text = text.substr(0, text.find('#'));
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] == ' ' || text[i] == '\t') {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
        statement_.tokens.push_back({std::string(text.substr(start, i - start)),
                                     clamp_int(static_cast<long long>(start) + 1)});
    }
    statement_.end_column = clamp_int(static_cast<long long>(text.size()) + 1);
}

// One JSON object becomes one statement a key, in the order of
// json_keywords. A key's value gives the operands: a scalar is one, an
// array one per element, true none, and an object (state, step, branch,
// lit) its parts in the order of its form (object_forms).
void CertificateReader::split_json() {
    using io::JsonValue;
    const JsonValue object = io::parse_json(line_, name_, clamp_int(line_number_));
    const int line = clamp_int(line_number_);
    if (object.type != JsonValue::Type::object)
        throw InputError(name_, line, object.column,
                         "found " + io::describe(object) +
                             ", expected a JSON object (one statement a line)");
    std::string known;
    for (std::string_view k : json_keywords)
        known += (known.empty() ? "\"" : ", \"") + std::string(k) + "\"";
    for (std::size_t i = 0; i < object.keys.size(); ++i) {
        bool found = false;
        for (std::string_view k : json_keywords) found = found || object.keys[i] == k;
        for (std::size_t j = 0; j < i && found; ++j)
            if (object.keys[j] == object.keys[i])
                throw InputError(name_, line, object.key_columns[i],
                                 "found a second key " + io::json_quoted(object.keys[i]) +
                                     ", expected each key once");
        if (!found)
            throw InputError(name_, line, object.key_columns[i],
                             "found the key " + io::json_quoted(object.keys[i]) +
                                 ", expected one of " + known);
    }
    if (object.keys.empty())
        throw InputError(name_, line, object.column,
                         "found an empty object, expected a certificate statement");

    bool first = true;
    for (std::string_view keyword : json_keywords) {
        for (std::size_t i = 0; i < object.keys.size(); ++i) {
            if (object.keys[i] != keyword) continue;
            Statement s;
            s.line = line_number_;
            s.tokens.push_back({object.keys[i], object.key_columns[i]});
            const JsonValue& value = object.items[i];
            s.end_column = value.column;
            if (value.type == JsonValue::Type::array) {
                for (const JsonValue& item : value.items) s.tokens.push_back(operand(item));
            } else if (const ObjectForm* form = object_form(keyword);
                       form && value.type == JsonValue::Type::object) {
                object_operands(value, *form, name_, line, s.tokens);
            } else if (value.type != JsonValue::Type::boolean || value.text != "true") {
                s.tokens.push_back(operand(value));
            }
            if (first)
                statement_ = std::move(s);
            else
                pending_.push_back(std::move(s));
            first = false;
        }
    }
}

const char* CertificateReader::end_of_statement() const {
    return format_ == CertificateFormat::text ? "end of line" : "no more values";
}

void CertificateReader::fail(std::size_t index, const std::string& expected) const {
    std::string found;
    int column = 0;
    if (index < statement_.tokens.size()) {
        found = io::quoted_token(statement_.tokens[index].text);
        column = statement_.tokens[index].column;
    } else {
        found = end_of_statement();
        column = statement_.end_column;
    }
    throw InputError(name_, clamp_int(statement_.line), column,
                     "found " + found + ", expected " + expected);
}

void CertificateReader::expect(std::string_view keyword, std::size_t operands,
                               const std::string& operand) const {
    const auto& tokens = statement_.tokens;
    if (tokens[0].text != keyword) fail(0, std::string("'").append(keyword).append("'"));
    if (tokens.size() < operands + 1) fail(tokens.size(), operand);
    if (tokens.size() > operands + 1) fail(operands + 1, end_of_statement());
}

Rational CertificateReader::number(std::size_t index) const {
    NumberToken token = read_number(statement_.tokens[index].text);
    if (token.status == NumberToken::Status::zero_denominator)
        fail(index, "a number with a nonzero denominator");
    if (token.status != NumberToken::Status::ok) fail(index, "a number");
    token.value.canonicalize(); // equality tests need canonical form
    return token.value;
}

Vector CertificateReader::vector(std::size_t first, int dim) const {
    Vector result;
    for (int j = 0; j < dim; ++j) result[j] = number(first + j);
    return result;
}

Integer CertificateReader::count(std::size_t index) const {
    const std::string& text = statement_.tokens[index].text;
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        fail(index, "a non-negative integer");
    return Integer(text, 10);
}

void CertificateReader::read_header(int dim) {
    const std::string dim_text = std::to_string(dim);
    // A file cut short is a verdict (IncompleteCertificate), but one with no
    // statement at all is no certificate: malformed, like one that starts
    // with anything but the header.
    if (!next())
        throw InputError(name_, clamp_int(std::max(line_number_, 1LL)), 1,
                         "found end of file, expected 'orthoray-certificate' (the file holds no "
                         "statement)");
    expect("orthoray-certificate", 1, "the format version 1");
    if (token(1) != "1") fail(1, "the format version 1");
    advance();
    expect("dim", 1, "'" + dim_text + "'");
    if (token(1) != dim_text) fail(1, "'" + dim_text + "' (the scene's dim)");
    advance();
}

} // namespace orthoray::certify
