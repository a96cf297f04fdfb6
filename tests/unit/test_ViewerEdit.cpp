// Viewer editing (ViewerEdit.h): the property table through the public
// setters, the undo/redo stack, numbered screenshot names, and saving an
// edited scene (ViewerScene::save) that reloads with the same objects.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <m3g/m3g.h>

#include "SampleScene.h"
#include "ViewerEdit.h"
#include "ViewerScene.h"

using namespace m3g;
using namespace m3gview;

namespace {

Edit makeEdit(Object3D& o, const char* property, std::vector<float> after) {
    Edit e;
    e.target = Ref<Object3D>(&o);
    e.property = findEditProperty(o, property);
    EXPECT_NE(e.property, nullptr) << property;
    e.after = std::move(after);
    return e;
}

std::string tempDir(const char* name) {
    const auto dir = std::filesystem::temp_directory_path() / ("m3g-viewer-edit-" + std::to_string(::getpid()) + "-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

}  // namespace

TEST(ViewerEdit, PropertiesFollowTheClass) {
    Ref<Material> m(new Material());
    std::vector<std::string> names;
    for (const EditProperty* p : editPropertiesOf(*m)) names.push_back(p->name);
    EXPECT_EQ(names, (std::vector<std::string>{"ambient", "diffuse", "emissive", "specular", "shininess"}));
    Ref<Group> g(new Group());
    names.clear();
    for (const EditProperty* p : editPropertiesOf(*g)) names.push_back(p->name);
    EXPECT_EQ(names, (std::vector<std::string>{"translation", "orientation", "scale", "rendering", "picking"}));
    Ref<AnimationController> c(new AnimationController());
    EXPECT_EQ(editPropertiesOf(*c).size(), 3u);
    EXPECT_EQ(findEditProperty(*g, "diffuse"), nullptr);
    EXPECT_EQ(findEditProperty(*c, "nonsense"), nullptr);
}

TEST(ViewerEdit, ColoursAreChannelsOfTheArgbInts) {
    Ref<Material> m(new Material());
    const EditProperty* diffuse = findEditProperty(*m, "diffuse");
    diffuse->set(*m, {1.0f, 0.0f, 0.2f, 0.6f}, 0);
    EXPECT_EQ(static_cast<unsigned>(m->getColor(Material::DIFFUSE)), 0x99FF0033u);
    const std::vector<float> back = diffuse->get(*m);
    ASSERT_EQ(back.size(), 4u);
    EXPECT_FLOAT_EQ(back[2], 0x33 / 255.0f);
    // Three channels keep the alpha the setter does not take.
    const EditProperty* ambient = findEditProperty(*m, "ambient");
    ambient->set(*m, {0.0f, 1.0f, 0.0f}, 0);
    EXPECT_EQ(m->getColor(Material::AMBIENT) & 0x00FFFFFF, 0x0000FF00);
}

TEST(ViewerEdit, UndoRedoRestoreTheValues) {
    Ref<Material> m(new Material());
    Ref<Group> g(new Group());
    const int diffuse0 = m->getColor(Material::DIFFUSE);
    EditStack stack;
    EXPECT_FALSE(stack.undo());
    EXPECT_FALSE(stack.redo());
    stack.perform(makeEdit(*m, "diffuse", {1, 0, 0, 1}));
    stack.perform(makeEdit(*g, "translation", {1, 2, 3}));
    stack.perform(makeEdit(*m, "shininess", {64}));
    EXPECT_EQ(stack.size(), 3u);
    EXPECT_FLOAT_EQ(m->getShininess(), 64.0f);
    EXPECT_EQ(static_cast<unsigned>(m->getColor(Material::DIFFUSE)), 0xFFFF0000u);

    EXPECT_TRUE(stack.undo());  // shininess
    EXPECT_FLOAT_EQ(m->getShininess(), 0.0f);
    EXPECT_TRUE(stack.undo());  // translation
    float t[3];
    g->getTranslation(t);
    EXPECT_FLOAT_EQ(t[0], 0.0f);
    EXPECT_TRUE(stack.undo());  // diffuse
    EXPECT_EQ(m->getColor(Material::DIFFUSE), diffuse0);
    EXPECT_FALSE(stack.undo());
    EXPECT_EQ(stack.applied(), 0u);

    EXPECT_TRUE(stack.redo());
    EXPECT_EQ(static_cast<unsigned>(m->getColor(Material::DIFFUSE)), 0xFFFF0000u);
    EXPECT_TRUE(stack.redo());
    g->getTranslation(t);
    EXPECT_FLOAT_EQ(t[2], 3.0f);
    // A new edit drops what could be redone (the shininess).
    stack.perform(makeEdit(*g, "rendering", {0}));
    EXPECT_FALSE(g->isRenderingEnabled());
    EXPECT_FALSE(stack.canRedo());
    EXPECT_EQ(stack.size(), 3u);
    EXPECT_TRUE(stack.undo());
    EXPECT_TRUE(g->isRenderingEnabled());
}

TEST(ViewerEdit, ASetterThatThrowsRecordsNothing) {
    Ref<Material> m(new Material());
    EditStack stack;
    EXPECT_THROW(stack.perform(makeEdit(*m, "shininess", {500})), IllegalArgumentException);  // 0..128
    EXPECT_EQ(stack.size(), 0u);
    EXPECT_THROW(stack.perform(makeEdit(*m, "shininess", {1, 2})), std::invalid_argument);
    Ref<AnimationController> c(new AnimationController());
    EXPECT_THROW(stack.perform(makeEdit(*c, "interval", {100, 50})), IllegalArgumentException);  // end < start
    EXPECT_EQ(stack.size(), 0u);
}

TEST(ViewerEdit, PushRecordsAnEditAlreadyApplied) {
    // The panel applies values live while dragging and records the whole drag once.
    Ref<Group> g(new Group());
    EditStack stack;
    const EditProperty* scale = findEditProperty(*g, "scale");
    scale->set(*g, {2, 2, 2}, 0);
    Edit e;
    e.target = Ref<Object3D>(g.get());
    e.property = scale;
    e.before = {1, 1, 1};
    e.after = {2, 2, 2};
    stack.push(e);
    EXPECT_TRUE(stack.undo());
    float s[3];
    g->getScale(s);
    EXPECT_FLOAT_EQ(s[1], 1.0f);
    EXPECT_TRUE(stack.redo());
    g->getScale(s);
    EXPECT_FLOAT_EQ(s[1], 2.0f);
}

TEST(ViewerEdit, OrientationAndControllerEditsRoundTrip) {
    Ref<Group> g(new Group());
    EditStack stack;
    stack.perform(makeEdit(*g, "orientation", {90, 0, 1, 0}));
    const std::vector<float> o = findEditProperty(*g, "orientation")->get(*g);
    EXPECT_NEAR(o[0], 90.0f, 1e-3f);
    EXPECT_NEAR(o[2], 1.0f, 1e-5f);
    EXPECT_TRUE(stack.undo());  // back to the identity (angle 0 about a zero axis)
    EXPECT_NEAR(findEditProperty(*g, "orientation")->get(*g)[0], 0.0f, 1e-5f);
    EXPECT_TRUE(stack.redo());

    Ref<AnimationController> c(new AnimationController());
    stack.perform(makeEdit(*c, "speed", {2.5f}));
    stack.perform(makeEdit(*c, "weight", {0.5f}));
    stack.perform(makeEdit(*c, "interval", {100, 900}));
    EXPECT_FLOAT_EQ(c->getSpeed(), 2.5f);
    EXPECT_FLOAT_EQ(c->getWeight(), 0.5f);
    EXPECT_EQ(c->getActiveIntervalStart(), 100);
    EXPECT_EQ(c->getActiveIntervalEnd(), 900);
    stack.undo();
    stack.undo();
    stack.undo();
    EXPECT_FLOAT_EQ(c->getSpeed(), 1.0f);
    EXPECT_FLOAT_EQ(c->getWeight(), 1.0f);
    EXPECT_EQ(c->getActiveIntervalEnd(), 0);
}

TEST(ViewerEdit, ScreenshotNamesAreNumberedAndNeverReused) {
    const std::string dir = tempDir("shots");
    EXPECT_EQ(nextScreenshotName(dir), dir + "/m3g-screenshot-0001.png");
    std::ofstream(dir + "/m3g-screenshot-0001.png") << "x";
    std::ofstream(dir + "/m3g-screenshot-0002.png") << "x";
    EXPECT_EQ(nextScreenshotName(dir), dir + "/m3g-screenshot-0003.png");
    std::filesystem::remove(dir + "/m3g-screenshot-0001.png");  // a gap is the next free number
    EXPECT_EQ(nextScreenshotName(dir), dir + "/m3g-screenshot-0001.png");
    EXPECT_EQ(nextScreenshotName("").rfind("m3g-screenshot-", 0), 0u);
    std::filesystem::remove_all(dir);
}

TEST(ViewerEdit, ASavedSceneReloadsWithTheEditsAndWithoutTheViewersNodes) {
    const std::string dir = tempDir("save");
    const std::string original = dir + "/sample.m3g", saved = dir + "/edited.m3g";
    {
        Ref<World> sample = m3gcli::buildSampleScene();
        Object3D* root = sample.get();
        Saver::save(original, std::span<Object3D* const>(&root, 1));
    }
    std::size_t objectCount = 0;  // the file's, before the viewer adds its camera and light
    {
        const std::vector<Ref<Object3D>> loaded = Loader::load(original);
        std::vector<Object3D*> roots;
        for (const auto& o : loaded) roots.push_back(o.get());
        objectCount = m3gcli::collectObjects(roots).size();
    }
    ViewerScene scene(original, 320, 240, false);
    // The first Material (by `m3g info` id) and a node.
    Material* material = nullptr;
    Node* node = nullptr;
    int materialId = -1, nodeId = -1;
    for (int id = 0; scene.object(id); ++id) {
        if (!material && (material = dynamic_cast<Material*>(scene.object(id)))) materialId = id;
        if (!node && dynamic_cast<Mesh*>(scene.object(id))) node = dynamic_cast<Node*>(scene.object(id)), nodeId = id;
    }
    ASSERT_NE(material, nullptr);
    ASSERT_NE(node, nullptr);
    EditStack stack;
    stack.perform(makeEdit(*material, "diffuse", {1, 0, 0, 1}));
    stack.perform(makeEdit(*material, "shininess", {42}));
    stack.perform(makeEdit(*node, "picking", {0}));
    stack.perform(makeEdit(*material, "emissive", {0, 0, 1}));
    stack.undo();  // the emissive edit is not saved
    scene.save(saved);

    const std::vector<Ref<Object3D>> back = Loader::load(saved);
    ASSERT_FALSE(back.empty());
    std::vector<Object3D*> roots;
    for (const auto& o : back) roots.push_back(o.get());
    // Loader::load gives the roots; ids count the same way as the original's.
    const m3gcli::ObjectNumbering numbering(roots);
    const std::vector<Object3D*> objects = m3gcli::collectObjects(roots);
    EXPECT_EQ(objects.size(), objectCount);  // no orbit camera, no headlight
    ASSERT_GT(objects.size(), static_cast<std::size_t>(std::max(materialId, nodeId)));
    auto* m2 = dynamic_cast<Material*>(objects[static_cast<std::size_t>(materialId)]);
    ASSERT_NE(m2, nullptr);
    EXPECT_EQ(static_cast<unsigned>(m2->getColor(Material::DIFFUSE)), 0xFFFF0000u);
    EXPECT_FLOAT_EQ(m2->getShininess(), 42.0f);
    EXPECT_EQ(m2->getColor(Material::EMISSIVE), material->getColor(Material::EMISSIVE));
    auto* n2 = dynamic_cast<Node*>(objects[static_cast<std::size_t>(nodeId)]);
    ASSERT_NE(n2, nullptr);
    EXPECT_FALSE(n2->isPickingEnabled());
    // The viewer's own camera and light are still in its World after the save.
    int cameras = 0, lights = 0;
    for (int i = 0; i < scene.world().getChildCount(); ++i) {
        cameras += dynamic_cast<Camera*>(scene.world().getChild(i).get()) ? 1 : 0;
        lights += dynamic_cast<Light*>(scene.world().getChild(i).get()) ? 1 : 0;
    }
    int cameras2 = 0, lights2 = 0;
    for (Object3D* o : objects) {
        cameras2 += dynamic_cast<Camera*>(o) ? 1 : 0;
        lights2 += dynamic_cast<Light*>(o) ? 1 : 0;
    }
    EXPECT_EQ(cameras, cameras2 + 1);  // + the orbit camera
    EXPECT_EQ(lights, lights2 + 1);    // + the headlight
    std::filesystem::remove_all(dir);
}
