// Writes the illumination part of a certificate, text or JSON Lines; the
// layout is in illumination_certificate_section.hpp and docs/certificates.md.
#include "certify/illumination_certificate_section.hpp"

#include <string>

namespace orthoray {

void CertificateWriter::IlluminationSection::branch(const Vector& point, const Vector& direction,
                                                    std::size_t ray, std::uint64_t reflections) {
    branch_state(point, direction);
    if (json())
        writer_.out_ << ", \"ray\": \"" << ray << "\", \"reflections\": \"" << reflections
                     << "\"}}\n";
    else
        writer_.out_ << " ray " << ray << " reflections " << reflections << '\n';
}

void CertificateWriter::IlluminationSection::branch(const Vector& point, const Vector& direction,
                                                    const Integer& intensity) {
    branch_state(point, direction);
    if (json())
        writer_.out_ << ", \"intensity\": \"" << intensity.get_str() << "\"}}\n";
    else
        writer_.out_ << " intensity " << intensity.get_str() << '\n';
}

// `branch X V` or the branch object up to its direction; the caller ends it.
void CertificateWriter::IlluminationSection::branch_state(const Vector& point,
                                                          const Vector& direction) {
    begin();
    std::ostream& out = writer_.out_;
    out << (json() ? "{\"branch\": {\"point\": " : "branch");
    writer_.write_vector(point);
    out << (json() ? ", \"direction\": " : "");
    writer_.write_vector(direction);
    ++branches_;
}

void CertificateWriter::IlluminationSection::lit(std::size_t target, std::uint64_t reflections,
                                                 std::size_t ray) {
    begin();
    if (json())
        writer_.out_ << "{\"lit\": {\"target\": \"" << target << "\", \"reflections\": \""
                     << reflections << "\", \"ray\": \"" << ray << "\"}}\n";
    else
        writer_.out_ << "lit " << target << " reflections " << reflections << " ray " << ray
                     << '\n';
    listed_ = true;
}

void CertificateWriter::IlluminationSection::lit(std::size_t target, std::uint64_t reflections,
                                                 std::size_t ray, const Integer& intensity) {
    begin();
    if (json())
        writer_.out_ << "{\"lit\": {\"target\": \"" << target << "\", \"reflections\": \""
                     << reflections << "\", \"ray\": \"" << ray << "\", \"intensity\": \""
                     << intensity.get_str() << "\"}}\n";
    else
        writer_.out_ << "lit " << target << " reflections " << reflections << " ray " << ray
                     << " intensity " << intensity.get_str() << '\n';
    listed_ = true;
}

void CertificateWriter::IlluminationSection::step(const Vector& point, const Vector& direction) {
    std::ostream& out = writer_.out_;
    out << (json() ? "{\"step\": {\"point\": " : "step");
    writer_.write_vector(point);
    out << (json() ? ", \"direction\": " : "");
    writer_.write_vector(direction);
    out << (json() ? "}}\n" : "\n");
}

void CertificateWriter::IlluminationSection::unlit(std::size_t target) {
    target_line("unlit", target);
}

void CertificateWriter::IlluminationSection::unknown(std::size_t target) {
    target_line("unknown", target);
}

void CertificateWriter::IlluminationSection::finish(const Answer& answer) {
    begin();
    if (!listed_)
        for (std::size_t t = 1; t <= writer_.scene_.targets.size(); ++t) unknown(t);
    const bool partial = answer.reason == Reason::limit;
    const std::string reason = to_string(answer.reason);
    const std::string states = std::to_string(branches_);
    std::ostream& out = writer_.out_;
    if (json())
        out << "{\"answer\": \"" << answer_word(answer) << "\", \"reason\": \"" << reason
            << "\", \"reflections\": \"" << answer.reflections.get_str() << "\", \"states\": \""
            << states << '"' << (partial ? ", \"partial\": true" : "") << "}\n{\"end\": true}\n";
    else
        out << "answer " << answer_word(answer) << "\nreason " << reason << "\nreflections "
            << answer.reflections.get_str() << "\nstates " << states << '\n'
            << (partial ? "partial\n" : "") << "end\n";
    out.flush();
}

bool CertificateWriter::IlluminationSection::json() const {
    return writer_.format_ == CertificateFormat::jsonl;
}

void CertificateWriter::IlluminationSection::begin() {
    if (begun_) return;
    writer_.out_ << (json() ? "{\"illumination\": true}\n" : "illumination\n");
    if (min_intensity_) {
        if (json())
            writer_.out_ << "{\"min-intensity\": \"" << min_intensity_->get_str() << "\"}\n";
        else
            writer_.out_ << "min-intensity " << min_intensity_->get_str() << '\n';
    }
    begun_ = true;
}

void CertificateWriter::IlluminationSection::target_line(const char* word, std::size_t target) {
    begin();
    if (json())
        writer_.out_ << "{\"" << word << "\": \"" << target << "\"}\n";
    else
        writer_.out_ << word << ' ' << target << '\n';
    listed_ = true;
}

} // namespace orthoray
