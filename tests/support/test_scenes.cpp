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

}  // namespace gbl::test
