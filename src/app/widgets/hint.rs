//! A picture's hint ("Drag to orbit..."): a tooltip at the pointer and above it, over the
//! picture the pointer rests on. egui draws a widget's tooltip under the widget, where, under
//! the shaded picture and the vector plot, it covered the band of Things to try whenever the
//! pointer rested on either.

/// Shows `text` as `picture`'s hover hint, at the pointer and above it (below it only where
/// there is no room above).
pub fn above_pointer(picture: &egui::Response, text: String) {
    let open = picture.enabled() && egui::Tooltip::should_show_tooltip(picture, false);
    let width = picture.ctx.global_style().spacing.tooltip_width;
    egui::Popup::from_response(picture)
        .kind(egui::PopupKind::Tooltip)
        .at_pointer()
        .align(egui::RectAlign::TOP_START)
        .align_alternatives(&[egui::RectAlign::TOP_END, egui::RectAlign::BOTTOM_START])
        .gap(12.0)
        .width(width)
        .sense(egui::Sense::hover())
        .open(open)
        .show(|ui| {
            ui.set_max_width(width);
            ui.label(text);
        });
}
