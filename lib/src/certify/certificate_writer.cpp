// Streams the certificate of docs/certificates.md: points as they come, the
// verdict at the end. Only the first reflection state and the last direction
// are kept, so memory does not grow with the path.
#include "orthoray/certificate.hpp"

namespace orthoray {
namespace {

void write_vector(std::ostream& out, const Vector& x, int dim) {
    for (int j = 0; j < dim; ++j) out << ' ' << to_string(x[j]);
}

} // namespace

CertificateWriter::CertificateWriter(std::ostream& out, const Scene& scene)
    : out_(out), scene_(scene) {
    out_ << "orthoray-certificate 1\ndim " << scene_.dim << '\n';
}

void CertificateWriter::visit(const Vector& point, const Vector& direction) {
    out_ << "point";
    write_vector(out_, point, scene_.dim);
    out_ << '\n';
    if (visits_ == 1) {
        first_reflection_point_ = point;
        first_reflection_direction_ = direction;
    }
    last_direction_ = direction;
    ++visits_;
}

void CertificateWriter::finish(const Answer& answer) {
    out_ << "answer " << answer_word(answer) << "\nreason " << to_string(answer.reason)
         << "\nreflections " << answer.reflections.get_str() << '\n';
    switch (answer.reason) {
    case Reason::hit:
        out_ << "target";
        write_vector(out_, scene_.target, scene_.dim);
        out_ << '\n';
        break;
    case Reason::escape:
        out_ << "direction";
        write_vector(out_, last_direction_, scene_.dim);
        out_ << '\n';
        break;
    case Reason::cycle:
        out_ << "state";
        write_vector(out_, first_reflection_point_, scene_.dim);
        write_vector(out_, first_reflection_direction_, scene_.dim);
        out_ << "\nperiod " << answer.reflections.get_str() << '\n';
        break;
    case Reason::limit:
        out_ << "partial\n";
        break;
    case Reason::absorbed:
        break;
    }
    out_ << "end\n";
    out_.flush();
}

} // namespace orthoray
