// scene_follow.cpp - what the viewer does when the scene it draws changes: a new model (its
// view, tree and a clean start), new copies, a model shown as it loads growing (everything
// kept), and the model before a cancelled load coming back with its view and parts.
#include <utility>

#include "app/viewer/viewer.h"

namespace app {

// A new scene: part IDs name other parts now. New copies keep the view, a new model opens
// at its own; a model shown as it loads keeps everything as it grows (grown), and Cancel
// brings back the model before it with its view and parts.
void Viewer::follow(SceneState::Change change) {
    using Change = SceneState::Change;
    if (change == Change::None) return;
    // The new scene exploded as the slider stands, before the camera frames it; its copy may
    // lie where the last one did, so the part details start over.
    scene_.explode(settings_.animation.animate ? 0.0f : document_.explode());
    partDetails_ = PartDetailsCache{};
    census_.forget(); // its parts were the scene's before
    if (change == Change::Grown) return grown();
    // A model's first partial scene replaces the model drawn: what Cancel brings back.
    const auto loading = scene_.loading();
    if (change == Change::Model && scene_.partial() && loading && loading->modelBefore)
        before_ = Before{camera_, document_.selection(), document_.section()};
    const scene::Scene& scene = scene_.scene();
    picking_.forget(frameNumber_);
    edgeHover_.forget();
    inspect_.forget();
    std::optional<Before> back =
        change == Change::Restored ? std::exchange(before_, {}) : std::nullopt;
    startClean(change); // selection, section, history: what belonged to the model before
    if (back) document_.bringBack(back->selection, back->section); // no undo step of them
    rebuildTree(false);
    if (change == Change::Model && scene_.partial()) // the tree is whole before the solids
        events_.say("loading", [&](util::JsonWriter& j) {
            j.member("state", "tree").member("nodes", tree_.size());
            j.member("objects", scene.objects.size());
        });
    if (back) {
        camera_ = back->camera;
        selectionChanged();
        partsChanged();
        return;
    }
    if (change != Change::Model) {
        camera_.setBounds(scene.bounds()); // more copies: same view, planes follow
        return;
    }
    remember(scene_.loaded().source);
    // A partial scene is framed on every object's box, the whole assembly, not on the few
    // solids meshed so far.
    const scene::Bounds bounds = scene_.partial() ? scene_.extent() : scene.bounds();
    scene::Camera initial = initialCamera(scene_.loaded(), aspect(), {}, bounds);
    if (scene_.loaded().settings.copies > 1) // copy 0's opening view, drawn back to take in all
        initial = scene::fitCamera(bounds, initial.eye - initial.target, initial.up, initial.fovY,
                                   aspect());
    // The model's up axis comes from the three-quarter view; --view turns from there; then it
    // is framed beside the panel, as F frames it, not partly under it.
    camera_ = OrbitCamera(initial, bounds, settings_.camera.standard);
    camera_.fit(aspect(), panelSpan());
    camera_.setHome(); // Home comes back here, beside the panel
    sayFitted();
}

// The model loading shows more solids, or is whole: the same part IDs, so the selection,
// hidden parts, X-ray, the view and the tree's open rows stay. What was worked out from the
// triangles before is worked out again, and the renderer, which takes a new scene with
// nothing selected or hidden, is handed them again (showParts).
void Viewer::grown() {
    drawnVersion_.reset();
    shell_.changedAt = frameNumber_; // the visible counts of earlier frames are stale
    edgeHover_.forget();
    inspect_.forget();
    camera_.setBounds(scene_.partial() ? scene_.extent() : scene_.scene().bounds());
    rebuildTree(true);
}

void Viewer::rebuildTree(bool keepOpen) {
    std::vector<scene::TreeRow> rows;
    if (!scene_.loaded().source.empty()) { // nothing open: no tree
        scene::AssemblyNode root =
            scene::assemblyTree(scene_.scene(), treeRootName(scene_.loaded()));
        scene::sortNatural(root); // the panel lists siblings by name, --tree in scene order
        rows = scene::treeRows(root);
    }
    namedSelection_ = {};
    selectedRow_.reset();
    if (!keepOpen || rows.size() != tree_.size()) {
        view_.treeOpen.clear();
        view_.treeShown.clear();
    }
    tree_ = std::move(rows);
}

} // namespace app
