// Editing in the viewer: the editable properties of the M3G objects (read
// and written through the public getters and setters only), an undo/redo
// command stack of edits, and the numbered screenshot names. No window, no
// ImGui: the Properties panel and the script commands use the same table,
// and the unit tests drive it directly.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <m3g/m3g.h>

namespace m3gview {

/// How a property is shown in the Properties panel.
enum class EditKind { Color3, Color4, Float, Float3, AngleAxis, Bool, Int2 };

/// One editable property of a class. Values are floats: colours as 0..1
/// channels (r, g, b[, a]), booleans 0/1, integers as floats.
struct EditProperty {
    const char* name;   ///< as the script's `edit` command names it
    const char* label;  ///< as the panel shows it
    EditKind kind;
    std::size_t count;  ///< number of values
    bool (*applies)(const m3g::Object3D&);
    std::vector<float> (*get)(const m3g::Object3D&);
    /// Applies values through the setters; `worldTime` is the animation
    /// time (AnimationController::setSpeed needs it). Throws what the
    /// setter throws (IAE for out-of-range values).
    void (*set)(m3g::Object3D&, const std::vector<float>&, int worldTime);
};

/// Every editable property, in panel order: Transformable (translation,
/// orientation, scale), Node (rendering, picking), Material (ambient,
/// diffuse, emissive, specular, shininess), AnimationController (speed,
/// weight, interval).
const std::vector<EditProperty>& editProperties();
/// The properties of `object`'s class, in panel order.
std::vector<const EditProperty*> editPropertiesOf(const m3g::Object3D& object);
/// A property by name that applies to `object`, or null.
const EditProperty* findEditProperty(const m3g::Object3D& object, const std::string& name);

/// One edit: the object, the property, its value before and after.
struct Edit {
    m3g::Ref<m3g::Object3D> target;
    const EditProperty* property = nullptr;
    std::vector<float> before, after;
    int worldTime = 0;
};

/// The undo/redo stack. push() records an edit already applied (the panel
/// applies values live while a widget is dragged); perform() applies and
/// records. A new edit drops what could be redone.
class EditStack {
public:
    void push(Edit edit);
    /// Applies `after` (through the setter) and records the edit; throws
    /// (recording nothing) when the setter throws.
    void perform(Edit edit);
    /// Applies the last edit's `before`; false when there is nothing to undo.
    bool undo();
    /// Applies the next undone edit's `after`; false when there is none.
    bool redo();
    bool canUndo() const noexcept { return done_ > 0; }
    bool canRedo() const noexcept { return done_ < edits_.size(); }
    std::size_t size() const noexcept { return edits_.size(); }
    /// Edits applied now (undone ones excluded).
    std::size_t applied() const noexcept { return done_; }
    /// The edit undo() would revert, or null.
    const Edit* lastApplied() const noexcept { return done_ ? &edits_[done_ - 1] : nullptr; }
    void clear() noexcept {
        edits_.clear();
        done_ = 0;
    }

private:
    std::vector<Edit> edits_;
    std::size_t done_ = 0;
};

/// "PROPERTY = v1 v2 ..." for messages.
std::string describe(const EditProperty& property, const std::vector<float>& values);

/// The first "m3g-screenshot-NNNN.png" (from 0001) in `folder` that does
/// not exist yet (the folder, then "/", then the name; "" is the current
/// folder and gives the bare name).
std::string nextScreenshotName(const std::string& folder = "");

}  // namespace m3gview
