#include "support/branch_certificate.hpp"

#include "engine/reference_step.hpp"

#include <map>
#include <set>
#include <sstream>
#include <utility>

namespace orthoray::test {
namespace {

using State = std::pair<Vector, Vector>;

struct StateOrder {
    bool operator()(const State& a, const State& b) const {
        for (int j = 0; j < 3; ++j)
            if (int c = cmp(a.first[j], b.first[j])) return c < 0;
        for (int j = 0; j < 3; ++j)
            if (int c = cmp(a.second[j], b.second[j])) return c < 0;
        return false;
    }
};

struct Edge {
    std::size_t to;
    Integer weight; // reflections along the stretch, plus 1 if the branch turns
};

struct Branch {
    State state;
    std::vector<Edge> edges;
    std::vector<std::optional<Integer>> first_pass; // per target: reflections into the stretch
    std::optional<std::pair<Integer, std::size_t>> label; // (K, ray from 1)
    std::optional<std::size_t> parent;                    // where the least label comes from
};

bool equal(const State& a, const State& b) {
    return !StateOrder{}(a, b) && !StateOrder{}(b, a);
}

std::string text_of(const Vector& x, int dim) {
    std::string s;
    for (int j = 0; j < dim; ++j) s.append(j ? " " : "").append(to_string(x[j]));
    return s;
}

class Builder {
public:
    Builder(const Scene& scene, std::size_t max_events) : scene_(scene), budget_(max_events) {}

    bool explore() {
        for (const Ray& ray : scene_.rays) add({ray.start, ray.direction});
        for (std::size_t b = 0; b < branches_.size(); ++b)
            if (!walk(b, nullptr, std::nullopt, std::nullopt)) return false;
        return true;
    }

    // Dijkstra on (K, ray): every edge keeps the ray and adds its weight.
    void label() {
        for (std::size_t r = 0; r < scene_.rays.size(); ++r) {
            Branch& b = branches_[index_.at({scene_.rays[r].start, scene_.rays[r].direction})];
            if (!b.label) b.label = std::make_pair(Integer(0), r + 1);
        }
        std::vector<bool> settled(branches_.size(), false);
        for (;;) {
            std::optional<std::size_t> next;
            for (std::size_t b = 0; b < branches_.size(); ++b)
                if (!settled[b] && branches_[b].label &&
                    (!next || *branches_[b].label < *branches_[*next].label))
                    next = b;
            if (!next) return;
            settled[*next] = true;
            for (const Edge& e : branches_[*next].edges) {
                const std::pair<Integer, std::size_t> via{branches_[*next].label->first + e.weight,
                                                          branches_[*next].label->second};
                Branch& to = branches_[e.to];
                if (!to.label || via < *to.label) {
                    to.label = via;
                    to.parent = *next;
                }
            }
        }
    }

    BranchCertificate write() {
        const int dim = scene_.dim;
        BranchCertificate c;
        std::ostringstream out;
        std::size_t line = 0;
        auto emit = [&](const std::string& s) {
            out << s << '\n';
            ++line;
        };
        emit("orthoray-certificate 1");
        emit("dim " + std::to_string(dim));
        emit("illumination");
        for (const Branch& b : branches_) {
            c.branch_lines.push_back(line);
            emit("branch " + text_of(b.state.first, dim) + " " + text_of(b.state.second, dim) +
                 " ray " + std::to_string(b.label->second) + " reflections " +
                 b.label->first.get_str());
        }
        Integer largest = 0;
        bool all = true;
        for (std::size_t t = 0; t < scene_.targets.size(); ++t) {
            std::optional<std::pair<Integer, std::size_t>> best;
            std::size_t from = 0;
            for (std::size_t b = 0; b < branches_.size(); ++b) {
                const auto& w = branches_[b].first_pass[t];
                if (!w) continue;
                const std::pair<Integer, std::size_t> at{branches_[b].label->first + *w,
                                                         branches_[b].label->second};
                if (!best || at < *best) best = at, from = b;
            }
            TargetAnswer answer;
            if (!best) {
                answer.status = TargetAnswer::Status::unlit;
                all = false;
                emit("unlit " + std::to_string(t + 1));
            } else {
                answer.status = TargetAnswer::Status::lit;
                answer.reflections = best->first;
                answer.ray = best->second;
                if (best->first > largest) largest = best->first;
                emit("lit " + std::to_string(t + 1) + " reflections " + best->first.get_str() +
                     " ray " + std::to_string(best->second));
                std::vector<std::string> steps;
                witness(from, t, steps);
                for (const std::string& s : steps) emit(s);
            }
            c.targets.push_back(answer);
        }
        emit(all ? "answer yes" : "answer no");
        emit(all ? "reason lit" : "reason unlit");
        emit("reflections " + largest.get_str());
        emit("states " + std::to_string(branches_.size()));
        emit("end");
        c.text = out.str();
        return c;
    }

private:
    std::size_t add(const State& s) {
        const auto [it, fresh] = index_.emplace(s, branches_.size());
        if (fresh) {
            branches_.push_back({s, {}, {}, std::nullopt, std::nullopt});
            branches_.back().first_pass.resize(scene_.targets.size());
        }
        return it->second;
    }

    // Walks branch b's stretch. Without `steps`: records its edges and
    // first passes, adding the branch states it ends at. With `steps`: the
    // witness lines of its events, up to the branch state `towards` or up
    // to the segment passing target `target`.
    bool walk(std::size_t b, std::vector<std::string>* steps, std::optional<State> towards,
              std::optional<std::size_t> target) {
        const int dim = scene_.dim;
        Vector p = branches_[b].state.first, v = branches_[b].state.second;
        Integer w = 0;
        std::set<State, StateOrder> seen;
        for (;;) {
            if (!steps && budget_-- == 0) return false;
            const engine::ReferenceEvent e = engine::reference_step(scene_, p, v);
            for (std::size_t t = 0; t < scene_.targets.size(); ++t) {
                if (!engine::reference_passes(scene_, scene_.targets[t], p, v, e)) continue;
                if (target == t) return true;
                if (!steps && !branches_[b].first_pass[t]) branches_[b].first_pass[t] = w;
            }
            if (e.escape || e.absorbed) return true;
            if (e.outgoing.size() >= 2) {
                for (const engine::Outgoing& o : e.outgoing) {
                    const State next{e.point, o.direction};
                    if (steps && towards && equal(next, *towards)) {
                        steps->push_back("step " + text_of(e.point, dim) + " " +
                                         text_of(o.direction, dim));
                        return true;
                    }
                    if (!steps) {
                        const std::size_t to = add(next);
                        branches_[b].edges.push_back({to, w + (o.reflection ? 1 : 0)});
                    }
                }
                return true;
            }
            if (steps)
                steps->push_back("step " + text_of(e.point, dim) + " " + text_of(e.direction, dim));
            if (e.outgoing.front().reflection) w += 1;
            p = e.point;
            v = e.direction;
            if (!seen.insert({p, v}).second) return true;
        }
    }

    // The witness of target t through branch b: the chain of least labels
    // back to a ray's start, then each stretch's events in order.
    void witness(std::size_t b, std::size_t t, std::vector<std::string>& steps) {
        std::vector<std::size_t> chain{b};
        while (branches_[chain.back()].parent) chain.push_back(*branches_[chain.back()].parent);
        const int dim = scene_.dim;
        const State& first = branches_[chain.back()].state;
        steps.push_back("step " + text_of(first.first, dim) + " " + text_of(first.second, dim));
        for (std::size_t i = chain.size() - 1; i > 0; --i)
            walk(chain[i], &steps, branches_[chain[i - 1]].state, std::nullopt);
        walk(b, &steps, std::nullopt, t);
    }

    const Scene& scene_;
    std::size_t budget_;
    std::vector<Branch> branches_;
    std::map<State, std::size_t, StateOrder> index_;
};

} // namespace

std::optional<BranchCertificate> branch_certificate(const Scene& scene, std::size_t max_events) {
    Builder builder(scene, max_events);
    if (!builder.explore()) return std::nullopt;
    builder.label();
    return builder.write();
}

std::string as_json_lines(const std::string& text) {
    std::istringstream in(text);
    std::ostringstream out;
    auto quoted = [](const std::vector<std::string>& t, std::size_t from, std::size_t n) {
        std::string s = "[";
        for (std::size_t i = 0; i < n; ++i)
            s.append(i ? ",\"" : "\"").append(t[from + i]).append("\"");
        return s + "]";
    };
    std::string verdict;
    std::size_t dim = 2;
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::vector<std::string> t;
        for (std::string w; words >> w;) t.push_back(w);
        const std::string& k = t[0];
        if (k == "orthoray-certificate") continue;
        if (k == "dim") {
            dim = std::stoul(t[1]);
            out << "{\"orthoray-certificate\": 1, \"dim\": " << t[1] << "}\n";
        } else if (k == "illumination") {
            out << "{\"illumination\": true}\n";
        } else if (k == "branch") {
            out << "{\"branch\": {\"point\": " << quoted(t, 1, dim)
                << ", \"direction\": " << quoted(t, 1 + dim, dim) << ", \"ray\": \""
                << t[2 * dim + 2] << "\", \"reflections\": \"" << t[2 * dim + 4] << "\"}}\n";
        } else if (k == "step") {
            out << "{\"step\": {\"point\": " << quoted(t, 1, dim)
                << ", \"direction\": " << quoted(t, 1 + dim, dim) << "}}\n";
        } else if (k == "lit") {
            out << "{\"lit\": {\"target\": \"" << t[1] << "\", \"reflections\": \"" << t[3]
                << "\", \"ray\": \"" << t[5] << "\"}}\n";
        } else if (k == "unlit" || k == "unknown") {
            out << "{\"" << k << "\": \"" << t[1] << "\"}\n";
        } else if (k == "answer" || k == "reason" || k == "reflections" || k == "states") {
            verdict.append(verdict.empty() ? "{\"" : ", \"").append(k).append("\": \"");
            verdict.append(t[1]).append("\"");
        } else if (k == "end") {
            out << verdict << "}\n{\"end\": true}\n";
        }
    }
    return out.str();
}

} // namespace orthoray::test
