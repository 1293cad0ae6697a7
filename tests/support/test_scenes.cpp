// Analytic test scenes.
#include "test_scenes.h"

#include "scene/mesh_builder.h"

#include <glm/gtc/matrix_transform.hpp>

namespace gbl::test {

SceneData floorScene() {
    SceneData s;
    s.source = "test floor";
    Material m;
    m.name = "floor";
    m.baseColorFactor = glm::vec4(kPlaneAlbedo, 1.0f);
    m.specularFactor = kPlaneSpecular;
    s.materials.push_back(m);
    MeshData plane = makePlane({40.0f, 40.0f});
    plane.material = 0;
    s.meshes.push_back(plane);
    s.instances.push_back({0, glm::mat4(1.0f)});
    return s;
}

SceneData floorAndWallScene() {
    SceneData s = floorScene();
    MeshData wall = makeBox({6.0f, 4.0f, 0.2f});
    wall.material = 0;
    s.meshes.push_back(wall);
    s.instances.push_back({1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f, -0.1f))});
    return s;
}

PointLight floorTestLight() {
    PointLight light;
    light.position = {2.5f, 1.0f, 0.0f};
    light.color = {1.0f, 0.8f, 0.6f};
    light.intensity = 1.5f;
    light.kc = 1.0f;
    light.kl = 0.7f;
    light.kq = 1.8f;
    return light;
}

PipelineSettings plainSettings() {
    PipelineSettings s;
    s.lightCubes = false;
    s.ambient = glm::vec3(0.03f);
    return s;
}

Camera lookingAt(glm::vec3 from, glm::vec3 target) {
    Camera c;
    c.position = from;
    c.nearPlane = 0.1f;
    c.farPlane = 100.0f;
    c.lookAt(target);
    return c;
}

Ray pixelRay(Camera const& c, int w, int h, int x, int y) {
    glm::mat4 const inv = glm::inverse(c.projection(float(w) / float(h)) * c.view());
    float const nx = (float(x) + 0.5f) / float(w) * 2.0f - 1.0f;
    float const ny = 1.0f - (float(y) + 0.5f) / float(h) * 2.0f;
    glm::vec4 const a = inv * glm::vec4(nx, ny, -1.0f, 1.0f), b = inv * glm::vec4(nx, ny, 1.0f, 1.0f);
    glm::vec3 const pa = glm::vec3(a) / a.w, pb = glm::vec3(b) / b.w;
    return {pa, glm::normalize(pb - pa)};
}

}  // namespace gbl::test
