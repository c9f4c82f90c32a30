#include "scene_checks.hpp"

#include "orthoray/parse.hpp"

#include <algorithm>

namespace orthoray::cli {

void require_intensities(const Scene& scene, const std::string& file) {
    for (const Ray& ray : scene.rays)
        if (!ray.intensity)
            throw InputError(file, ray.line, std::max(ray.column, 1),
                             "found a ray without an intensity, expected 'intensity N' on every "
                             "ray for --min-intensity");
}

void require_one_intense_ray(const Scene& scene, const std::string& file) {
    if (scene.rays.size() > 1)
        throw InputError(file, scene.rays[1].line, std::max(scene.rays[1].column, 1),
                         "found a second ray, expected one ray for --from-scene (a realistic "
                         "model has one source)");
    if (!scene.ray().intensity)
        throw InputError(file, scene.ray().line, std::max(scene.ray().column, 1),
                         "found a ray without an intensity, expected 'intensity N' on the ray "
                         "for --from-scene");
}

} // namespace orthoray::cli
