// The realistic-model reader (docs/realistic-scenes.md): line by line, one
// statement a line, every problem one InputError at its line and column.
#include "io/quoted_token.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/realistic.hpp"

#include <cctype>
#include <map>
#include <set>
#include <string_view>
#include <tuple>

namespace orthoray {
namespace {

struct Token {
    std::string_view text;
    int column;
};

class ModelReader {
public:
    ModelReader(const std::string& text, const std::string& file) : text_(text), file_(file) {}

    RealisticModel read() {
        std::size_t begin = 0;
        int line = 0;
        while (begin <= text_.size()) {
            ++line;
            const std::size_t end = std::min(text_.find('\n', begin), text_.size());
            std::string_view content = text_.substr(begin, end - begin);
            if (!content.empty() && content.back() == '\r') content.remove_suffix(1);
            statement(split(content), line);
            last_line_ = line;
            last_column_ = static_cast<int>(content.size()) + 1;
            begin = end + 1;
        }
        if (!header_) missing("'realistic 1' as the first statement");
        if (!source_) missing("a 'source' statement");
        if (!receiver_) missing("a 'receiver' statement");
        if (!eps_) missing("an 'eps' statement");
        return std::move(model_);
    }

private:
    std::string_view text_;
    std::string file_;
    RealisticModel model_;
    std::map<std::string, std::size_t, std::less<>> names_;
    std::set<std::tuple<std::size_t, std::size_t, std::size_t>> triples_seen_;
    std::set<std::size_t> legs_seen_;
    bool header_ = false, source_ = false, receiver_ = false, eps_ = false;
    int line_ = 0, last_line_ = 1, last_column_ = 1;

    [[noreturn]] void fail(const Token& at, const std::string& expected) const {
        throw InputError(file_, line_, at.column,
                         "found " + io::quoted_token(at.text) + ", expected " + expected);
    }
    [[noreturn]] void missing(const std::string& expected) const {
        throw InputError(file_, last_line_, last_column_,
                         "found the end of the file, expected " + expected);
    }

    std::vector<Token> split(std::string_view content) const {
        std::vector<Token> tokens;
        std::size_t i = 0;
        while (i < content.size()) {
            if (content[i] == '#') break;
            if (content[i] == ' ' || content[i] == '\t') {
                ++i;
                continue;
            }
            const std::size_t start = i;
            while (i < content.size() && content[i] != ' ' && content[i] != '\t' &&
                   content[i] != '#')
                ++i;
            tokens.push_back({content.substr(start, i - start), static_cast<int>(start) + 1});
        }
        return tokens;
    }

    // A token past the end of a line: reported at the line's end.
    Token at(const std::vector<Token>& tokens, std::size_t k, int end_column) const {
        return k < tokens.size() ? tokens[k] : Token{"the end of the line", end_column};
    }

    void statement(const std::vector<Token>& t, int line) {
        line_ = line;
        if (t.empty()) return;
        const int end = t.back().column + static_cast<int>(t.back().text.size());
        auto need = [&](std::size_t count, const std::string& what) {
            if (t.size() < count)
                throw InputError(file_, line_, end, "found the end of the line, expected " + what);
            if (t.size() > count && t[0].text != "object" && t[0].text != "triple")
                fail(t[count], "the end of the line");
        };
        if (!header_) {
            if (t[0].text != "realistic") fail(t[0], "'realistic 1' as the first statement");
            need(2, "the format version 1");
            if (t[1].text != "1") fail(t[1], "the format version 1");
            header_ = true;
            return;
        }
        const std::string_view word = t[0].text;
        if (word == "object") {
            need(2, "an object name");
            for (std::size_t k = 1; k < t.size(); ++k) declare(t[k]);
        } else if (word == "source") {
            need(3, "the source object and the intensity it emits");
            once(source_, t[0]);
            model_.source = object(t[1]);
            model_.emitted = natural(t[2]);
        } else if (word == "receiver") {
            need(2, "the receiver object");
            once(receiver_, t[0]);
            model_.receiver = object(t[1]);
            if (source_ && model_.receiver == model_.source)
                fail(t[1], "a receiver other than the source");
        } else if (word == "eps") {
            need(2, "eps, a natural number");
            once(eps_, t[0]);
            model_.eps = natural(t[1]);
        } else if (word == "pair") {
            need(3, "the source and an object it reaches");
            if (!source_) fail(t[0], "'source' before the first 'pair'");
            if (object(t[1]) != model_.source) fail(t[1], "the source object");
            const std::size_t to = object(t[2]);
            if (to == model_.source) fail(t[2], "an object other than the source");
            if (!legs_seen_.insert(to).second) fail(t[2], "an object not paired before");
            model_.first_legs.push_back(to);
        } else if (word == "triple") {
            triple(t, end);
        } else {
            fail(t[0], "realistic, object, source, receiver, eps, pair or triple");
        }
    }

    void triple(const std::vector<Token>& t, int end) {
        if (t.size() < 5) {
            const Token gap = at(t, t.size(), end);
            fail(gap, t.size() < 4 ? "three objects" : "'scale' or 'table'");
        }
        Triple triple{object(t[1]), object(t[2]), object(t[3]), {}};
        if (triple.via == triple.from) fail(t[2], "an object other than the one before it");
        if (triple.to == triple.via) fail(t[3], "an object other than the one before it");
        if (!triples_seen_.insert({triple.from, triple.via, triple.to}).second)
            fail(t[1], "a triple not given before");
        if (t[4].text == "scale") {
            if (t.size() != 6) fail(at(t, 6, end), t.size() < 6 ? "P/Q" : "the end of the line");
            const Rational share = number(t[5]);
            if (share < 0 || share > 1) fail(t[5], "a share P/Q from 0 to 1");
            triple.transfer.kind = Transfer::Kind::scale;
            triple.transfer.p = share.get_num();
            triple.transfer.q = share.get_den();
        } else if (t[4].text == "table") {
            if (t.size() < 6) fail(at(t, 5, end), "steps THRESHOLD:VALUE");
            triple.transfer.kind = Transfer::Kind::table;
            for (std::size_t k = 5; k < t.size(); ++k) step(t[k], triple.transfer);
        } else {
            fail(t[4], "'scale' or 'table'");
        }
        model_.triples.push_back(std::move(triple));
    }

    // THRESHOLD:VALUE; the steps must keep the function monotone and never
    // above its argument (docs/realistic-scenes.md).
    void step(const Token& token, Transfer& transfer) const {
        const std::size_t colon = token.text.find(':');
        if (colon == std::string_view::npos) fail(token, "a step THRESHOLD:VALUE");
        const Integer threshold = natural({token.text.substr(0, colon), token.column});
        // The value's own column, so that a bad one is pointed at, not the step.
        const Integer value =
            natural({token.text.substr(colon + 1), token.column + static_cast<int>(colon) + 1});
        if (!transfer.thresholds.empty() && threshold <= transfer.thresholds.back())
            fail(token, "thresholds in increasing order");
        if (!transfer.values.empty() && value < transfer.values.back())
            fail(token, "values that do not decrease (a monotone transfer)");
        if (value > threshold) fail(token, "a value at most its threshold (intensity never grows)");
        transfer.thresholds.push_back(threshold);
        transfer.values.push_back(value);
    }

    void once(bool& seen, const Token& token) const {
        if (seen) fail(token, "one '" + std::string(token.text) + "' statement");
        seen = true;
    }

    void declare(const Token& token) {
        for (const char c : token.text)
            if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-')
                fail(token, "an object name (letters, digits, '_' and '-')");
        if (!names_.emplace(std::string(token.text), model_.objects.size()).second)
            fail(token, "a name not declared before");
        model_.objects.emplace_back(token.text);
    }

    std::size_t object(const Token& token) const {
        const auto it = names_.find(token.text);
        if (it == names_.end()) fail(token, "an object declared by 'object'");
        return it->second;
    }

    Rational number(const Token& token) const {
        const NumberToken n = read_number(token.text);
        if (n.status != NumberToken::Status::ok) fail(token, "a number like 1/2");
        return n.value;
    }

    Integer natural(const Token& token) const {
        if (token.text.empty() || token.text.find_first_not_of("0123456789") != std::string::npos)
            fail(token, "a natural number");
        return Integer(std::string(token.text));
    }
};

} // namespace

RealisticModel read_realistic(const std::string& text, const std::string& file) {
    return ModelReader(text, file).read();
}

} // namespace orthoray
