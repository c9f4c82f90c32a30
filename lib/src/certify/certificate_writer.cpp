// Streams the certificate of docs/certificates.md: points as they come, the
// verdict at the end. Only the first reflection state and the last direction
// are kept, so memory does not grow with the path. The JSON Lines variant
// holds the same statements: the header, one line a point, one verdict line
// and an end line; numbers are strings, so nothing is rounded.
#include "orthoray/certificate.hpp"

namespace orthoray {

CertificateWriter::CertificateWriter(std::ostream& out, const Scene& scene,
                                     CertificateFormat format)
    : out_(out), scene_(scene), format_(format) {
    if (format_ == CertificateFormat::jsonl)
        out_ << "{\"orthoray-certificate\": 1, \"dim\": " << scene_.dim << "}\n";
    else
        out_ << "orthoray-certificate 1\ndim " << scene_.dim << '\n';
}

// Text: " 1 7/2"; JSON: ["1", "7/2"].
void CertificateWriter::write_vector(const Vector& x) {
    const bool json = format_ == CertificateFormat::jsonl;
    if (json) out_ << '[';
    for (int j = 0; j < scene_.dim; ++j) {
        if (json)
            out_ << (j ? ", \"" : "\"") << to_string(x[j]) << '"';
        else
            out_ << ' ' << to_string(x[j]);
    }
    if (json) out_ << ']';
}

void CertificateWriter::visit(const Vector& point, const Vector& direction) {
    out_ << (format_ == CertificateFormat::jsonl ? "{\"point\": " : "point");
    write_vector(point);
    out_ << (format_ == CertificateFormat::jsonl ? "}\n" : "\n");
    if (visits_ == 1) {
        first_reflection_point_ = point;
        first_reflection_direction_ = direction;
    }
    last_direction_ = direction;
    ++visits_;
}

void CertificateWriter::finish(const Answer& answer) {
    const bool json = format_ == CertificateFormat::jsonl;
    // A statement: `name operands` on its own line, or `"name": operands`
    // inside the one verdict object.
    auto statement = [&](const char* name) -> std::ostream& {
        return json ? out_ << ", \"" << name << "\": " : out_ << name;
    };
    auto end_statement = [&] {
        if (!json) out_ << '\n';
    };
    const std::string reflections = answer.reflections.get_str();
    if (json)
        out_ << "{\"answer\": \"" << answer_word(answer) << "\", \"reason\": \""
             << to_string(answer.reason) << "\", \"reflections\": \"" << reflections << '"';
    else
        out_ << "answer " << answer_word(answer) << "\nreason " << to_string(answer.reason)
             << "\nreflections " << reflections << '\n';
    switch (answer.reason) {
    case Reason::hit:
        statement("target");
        write_vector(scene_.target);
        end_statement();
        break;
    case Reason::escape:
        statement("direction");
        write_vector(last_direction_);
        end_statement();
        break;
    case Reason::cycle:
        if (json) {
            out_ << ", \"state\": {\"point\": ";
            write_vector(first_reflection_point_);
            out_ << ", \"direction\": ";
            write_vector(first_reflection_direction_);
            out_ << "}, \"period\": \"" << reflections << '"';
        } else {
            out_ << "state";
            write_vector(first_reflection_point_);
            write_vector(first_reflection_direction_);
            out_ << "\nperiod " << reflections << '\n';
        }
        break;
    case Reason::limit:
        statement("partial") << (json ? "true" : "");
        end_statement();
        break;
    case Reason::absorbed:
        break;
    }
    out_ << (json ? "}\n{\"end\": true}\n" : "end\n");
    out_.flush();
}

} // namespace orthoray
