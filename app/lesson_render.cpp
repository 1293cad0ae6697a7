// Headless lesson steps: the reference frame, the step's frame, the read-backs and the claim.
#include "lesson_render.h"

namespace gbl {

LessonStepFrame renderLessonStep(Renderer& renderer, ui::LessonStep const& step) {
    LessonStepFrame out;
    ui::LessonSnapshot const& s = step.state;
    glm::ivec2 const size{renderer.width(), renderer.height()};
    out.pixel = ui::lessonPixel(s.pixel.value_or(glm::vec2(0.5f)), size);
    ui::ClaimImages images;
    if (step.claim && step.claim->reference) {
        renderer.render({s.camera, s.lights, *step.claim->reference, true});
        images.referenceLighting = renderer.readAttachment(Attachment::Lighting);
        images.referenceDisplay = renderer.readAttachment(Attachment::Final);
        if (step.claim->reference->view == DebugView::Heatmap)
            images.referenceCoverage = renderer.readAttachment(Attachment::Coverage);
    }
    out.stats = renderer.render({s.camera, s.lights, s.pipeline, true});
    if (!step.claim) return out;
    images.lighting = renderer.readAttachment(Attachment::Lighting);
    images.display = renderer.readAttachment(Attachment::Final);
    images.position = renderer.readAttachment(Attachment::Position);
    images.normal = renderer.readAttachment(Attachment::Normal);
    images.albedoSpec = renderer.readAttachment(Attachment::AlbedoSpec);
    images.depth = renderer.readAttachment(Attachment::Depth);
    if (s.pipeline.view == DebugView::Heatmap || s.pipeline.view == DebugView::TileLights)
        images.coverage = renderer.readAttachment(Attachment::Coverage);
    images.complexShare = out.stats.complexPixelShare;
    out.claim = ui::checkClaim(*step.claim, {s.camera, s.lights, s.pipeline, out.pixel}, images);
    return out;
}

}  // namespace gbl
