// Reads a certificate (docs/certificates.md) one statement at a time, in
// either format: text, one statement a line, or JSON Lines, where one JSON
// object a line holds one or more statements as keys. Both become the same
// statements (a keyword and its operand tokens, each with its column), so
// what is checked does not depend on the format. Pure parsing: no geometry.
#pragma once

#include "orthoray/certificate.hpp"
#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

#include <cstddef>
#include <deque>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace orthoray::certify {

// Thrown when the stream ends before a statement that must come: a
// truncated file is a verdict (it never verifies), not a syntax error.
struct IncompleteCertificate {};

class CertificateReader {
public:
    struct Token {
        std::string text;
        int column = 0; // 1-based
    };

    // The format is recognised from the first non-blank line: JSON Lines
    // when it starts with '{', text otherwise.
    CertificateReader(std::istream& in, const std::string& name);

    // Moves to the next statement; false at the end of the stream.
    bool next();
    // Like next(), but the stream must not end here.
    void advance();

    CertificateFormat format() const { return format_; }
    // The line of the current statement, for messages that point back at it.
    long long line() const { return statement_.line; }
    std::string_view keyword() const { return statement_.tokens[0].text; }
    std::string_view token(std::size_t index) const { return statement_.tokens[index].text; }
    std::size_t size() const { return statement_.tokens.size(); }

    // The token at `index` (or the end of the statement) is wrong.
    [[noreturn]] void fail(std::size_t index, const std::string& expected) const;

    // The statement must be `keyword` followed by exactly `operands` tokens,
    // each described by `operand` in the error when it is missing.
    void expect(std::string_view keyword, std::size_t operands, const std::string& operand) const;

    // Reads the two header statements, `orthoray-certificate 1` and
    // `dim D` with D the scene's dimension, and moves past them. A stream
    // with no statement at all is an InputError, not IncompleteCertificate.
    void read_header(int dim);

    // What a statement ends with, as error messages say it.
    const char* end_of_statement() const;

    Rational number(std::size_t index) const;
    // `dim` numbers from token `first` on; the unused slots stay zero.
    Vector vector(std::size_t first, int dim) const;
    // Counts are written in full, so only plain digits are accepted; they
    // may exceed 64 bits.
    Integer count(std::size_t index) const;

private:
    struct Statement {
        std::vector<Token> tokens;
        long long line = 0;
        int end_column = 1; // where a missing token is reported
    };

    bool read_line();
    void split_text();
    void split_json();

    std::istream& in_;
    const std::string& name_;
    CertificateFormat format_ = CertificateFormat::text;
    bool format_known_ = false;
    std::string line_; // reused, so memory does not grow with the file
    long long line_number_ = 0;
    Statement statement_;
    std::deque<Statement> pending_; // the other statements of a JSON line
};

} // namespace orthoray::certify
