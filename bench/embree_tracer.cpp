// INEXACT COMPARISON BASELINE -- NOT PART OF ORTHORAY. See the header.
//
// Written as a renderer's bounce loop on purpose: Embree intersects in
// single precision, the hit point is origin + t * direction, and every test
// has a tolerance. Do not "fix" it; it is the thing being compared against.
#include "embree_tracer.hpp"

#include "bench_util.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace orthoray::bench {

std::string embree_unsupported(const Scene& scene) {
    for (const Element& e : scene.elements) {
        if (e.kind == ElementKind::splitter) return "a splitter";
        if (e.one_sided()) return "a one-sided element";
        if (e.is_diagonal()) return "a diagonal element";
    }
    return "";
}

class EmbreeTracer::Impl {
public:
    Impl(const Scene& scene, bool robust, double tnear) : dim_(scene.dim) {
        const auto begin = std::chrono::steady_clock::now();
        if (const std::string why = embree_unsupported(scene); !why.empty())
            throw std::invalid_argument("the Embree tracer takes no scene with " + why);
        double size = 1;
        auto grow = [&](double x) { size = std::max(size, std::fabs(x)); };
        // Each element's corners lo and hi, every coordinate converted once.
        const std::size_t n = scene.elements.size();
        std::vector<std::array<double, 6>> box(n);
        for (std::size_t i = 0; i < n; ++i)
            for (int j = 0; j < dim_; ++j) {
                box[i][j] = to_double(scene.elements[i].lo[j]);
                box[i][3 + j] = to_double(scene.elements[i].hi[j]);
                grow(box[i][j]), grow(box[i][3 + j]);
            }
        double length = 0;
        for (int j = 0; j < dim_; ++j) {
            start_[j] = to_double(scene.ray().start[j]);
            target_[j] = to_double(scene.target()[j]);
            dir_[j] = to_double(scene.ray().direction[j]);
            length += dir_[j] * dir_[j];
            grow(start_[j]);
            grow(target_[j]);
        }
        for (int j = 0; j < dim_; ++j) dir_[j] /= std::sqrt(length);
        eps_ = tnear * size;

        device_ = rtcNewDevice("threads=1");
        if (!device_) throw std::runtime_error("rtcNewDevice failed");
        scene_ = rtcNewScene(device_);
        rtcSetSceneFlags(scene_, robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_QUAD);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * n));
        auto* quads = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), n));
        for (std::size_t i = 0; i < n; ++i) {
            const Element& e = scene.elements[i];
            absorber_.push_back(e.kind == ElementKind::absorber);
            // The quad's corners: in 3D the rectangle's, in 2D the segment
            // extruded to z = -size and +size.
            std::array<std::array<double, 3>, 4> corner{};
            const int a = e.axis;
            const int u = dim_ == 3 ? (a + 1) % 3 : 1 - a, w = dim_ == 3 ? (a + 2) % 3 : 2;
            const double ulo = box[i][u], uhi = box[i][3 + u];
            const double wlo = dim_ == 3 ? box[i][w] : -size;
            const double whi = dim_ == 3 ? box[i][3 + w] : size;
            const double us[4] = {ulo, uhi, uhi, ulo}, ws[4] = {wlo, wlo, whi, whi};
            for (int k = 0; k < 4; ++k) {
                corner[k][a] = box[i][a]; // the offset: lo and hi agree on the normal axis
                corner[k][u] = us[k];
                corner[k][w] = ws[k];
                for (int j = 0; j < 3; ++j)
                    vertices[12 * i + 3 * k + j] = static_cast<float>(corner[k][j]);
                quads[4 * i + k] = static_cast<unsigned>(4 * i + k);
            }
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(scene_);
        if (rtcGetDeviceError(device_) != RTC_ERROR_NONE)
            throw std::runtime_error("Embree could not build the scene");
        setup_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    }

    ~Impl() {
        if (scene_) rtcReleaseScene(scene_);
        if (device_) rtcReleaseDevice(device_);
    }
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;

    EmbreeAnswer trace(std::uint64_t max_steps, const Visit& visit) const {
        EmbreeAnswer answer;
        answer.setup_seconds = setup_seconds;
        double p[3] = {start_[0], start_[1], start_[2]}, v[3] = {dir_[0], dir_[1], dir_[2]};
        double first_p[3] = {}, first_v[3] = {};
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (std::uint64_t reflections = 0;;) {
            RTCRayHit q{};
            q.ray.org_x = static_cast<float>(p[0]);
            q.ray.org_y = static_cast<float>(p[1]);
            q.ray.org_z = static_cast<float>(p[2]);
            q.ray.dir_x = static_cast<float>(v[0]);
            q.ray.dir_y = static_cast<float>(v[1]);
            q.ray.dir_z = static_cast<float>(v[2]);
            q.ray.tnear = static_cast<float>(eps_);
            q.ray.tfar = std::numeric_limits<float>::infinity();
            q.ray.mask = ~0u;
            q.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            q.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene_, &context, &q);
            const bool found = q.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            const double t = found ? q.ray.tfar : std::numeric_limits<double>::infinity();
            if (passes_target(p, v, t)) return done(answer, Reason::hit, reflections);
            if (!found) return done(answer, Reason::escape, reflections);
            for (int j = 0; j < 3; ++j) p[j] += t * v[j];
            if (absorber_[q.hit.primID]) return done(answer, Reason::absorbed, reflections);
            if (reflections == max_steps) return done(answer, Reason::limit, reflections);
            // The quad's normal is (up to rounding) along one axis: negate
            // the direction there.
            const float normal[3] = {std::fabs(q.hit.Ng_x), std::fabs(q.hit.Ng_y),
                                     std::fabs(q.hit.Ng_z)};
            v[std::max_element(normal, normal + 3) - normal] *= -1;
            ++reflections;
            if (visit && !visit(p, q.hit.primID)) return done(answer, Reason::limit, reflections);
            if (reflections == 1) {
                std::copy(p, p + 3, first_p);
                std::copy(v, v + 3, first_v);
            } else if (same_state(p, v, first_p, first_v)) {
                return done(answer, Reason::cycle, reflections - 1);
            }
        }
    }

    double setup_seconds = 0;

private:
    int dim_;
    double start_[3] = {}, target_[3] = {}, dir_[3] = {};
    double eps_ = 0;
    std::vector<bool> absorber_;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;

    static EmbreeAnswer done(EmbreeAnswer& a, Reason reason, std::uint64_t reflections) {
        a.reason = reason;
        a.reflections = reflections;
        return a;
    }

    // Whether the segment p + s v, 0 <= s <= t, passes within eps of the target.
    bool passes_target(const double* p, const double* v, double t) const {
        double s = 0;
        for (int j = 0; j < 3; ++j) s += (target_[j] - p[j]) * v[j];
        if (s < 0 || s > t) return false;
        for (int j = 0; j < 3; ++j)
            if (std::fabs(p[j] + s * v[j] - target_[j]) > eps_) return false;
        return true;
    }

    bool same_state(const double* p, const double* v, const double* fp, const double* fv) const {
        for (int j = 0; j < 3; ++j)
            if (std::fabs(p[j] - fp[j]) > eps_ || v[j] != fv[j]) return false;
        return true;
    }
};

EmbreeTracer::EmbreeTracer(const Scene& scene, bool robust, double tnear)
    : impl_(std::make_unique<Impl>(scene, robust, tnear)) {}
EmbreeTracer::~EmbreeTracer() = default;

EmbreeAnswer EmbreeTracer::trace(std::uint64_t max_steps, const Visit& visit) const {
    return impl_->trace(max_steps, visit);
}

double EmbreeTracer::setup_seconds() const {
    return impl_->setup_seconds;
}

} // namespace orthoray::bench
