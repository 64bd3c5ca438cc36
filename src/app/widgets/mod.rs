//! The widgets every panel builds with: the one number field ([`number_field`]), labelled
//! rows of sliders, vectors and colours ([`fields`]), arrows and their labels ([`arrows`]), the symbols' colours ([`palette`]) and
//! the placement of a diagram's labels ([`label_placement`]), and a picture's hover hint
//! ([`hint`]).

pub mod arrows;
pub mod fields;
pub mod hint;
pub mod label_placement;
pub mod number_field;
pub mod palette;
