//! `#[derive(Blank)]` gives a struct a private constructor `blank()` with every field at its
//! type's default: `Default::default()` for signals, flip-flops and sub-blocks,
//! `Constant::new(Default::default())` for rust-hdl's `Constant`s (which have no `Default`),
//! and `std::array::from_fn` for arrays of any length. A field marked `#[given]` (a
//! sub-block built from parameters, with no `Default`: a divider, a ROM) is given to
//! `blank` in a struct `<Name>Given` of those fields, by name.
//!
//! The rtl crate's units hold `Constant`s (widths, masks, lane numbers), so they cannot derive
//! `Default`, and their constructors used to name every port and register a second time,
//! each as `field: Default::default(),` (1,452 such lines). With the derive, a constructor
//! sets only what differs, `Self { mask: Constant::new(..), ..Self::blank() }`, and a port
//! is declared once, in the struct.

use proc_macro2::TokenStream;
use quote::quote;
use syn::{parse_macro_input, Data, DeriveInput, Fields, Type};

#[proc_macro_derive(Blank, attributes(given))]
pub fn derive_blank(input: proc_macro::TokenStream) -> proc_macro::TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    let fields = match &input.data {
        Data::Struct(s) => match &s.fields {
            Fields::Named(f) => &f.named,
            _ => return error(&input, "#[derive(Blank)] needs named fields"),
        },
        _ => return error(&input, "#[derive(Blank)] is for structs"),
    };
    let name = &input.ident;
    let (impl_generics, type_generics, where_clause) = input.generics.split_for_impl();
    let given = |f: &&syn::Field| f.attrs.iter().any(|a| a.path.is_ident("given"));
    let inits = fields.iter().map(|f| {
        let field = &f.ident;
        if given(&f) {
            quote!(#field: given.#field)
        } else {
            let value = blank(&f.ty);
            quote!(#field: #value)
        }
    });
    let given_fields: Vec<_> = fields.iter().filter(given).collect();
    if given_fields.is_empty() {
        return quote!(
            impl #impl_generics #name #type_generics #where_clause {
                /// Every field at its type's default and every `Constant` at 0
                /// (`#[derive(Blank)]`): the constructors set what differs and take the
                /// rest from here.
                fn blank() -> Self {
                    Self { #(#inits,)* }
                }
            }
        )
        .into();
    }
    let given_name = quote::format_ident!("{}Given", name);
    let generics = &input.generics;
    let decls = given_fields.iter().map(|f| {
        let (field, ty) = (&f.ident, &f.ty);
        quote!(#field: #ty)
    });
    let doc = format!("The fields of [`{name}`] its constructors build (`#[given]`): `{name}::blank`'s argument.");
    quote!(
        #[doc = #doc]
        struct #given_name #generics #where_clause {
            #(#decls,)*
        }

        impl #impl_generics #name #type_generics #where_clause {
            /// Every field at its type's default and every `Constant` at 0, but the
            /// `#[given]` ones, taken from `given` (`#[derive(Blank)]`): the constructors
            /// set what differs and take the rest from here.
            fn blank(given: #given_name #type_generics) -> Self {
                Self { #(#inits,)* }
            }
        }
    )
    .into()
}

/// A field's blank value.
fn blank(ty: &Type) -> TokenStream {
    match ty {
        Type::Array(a) => {
            let element = blank(&a.elem);
            quote!(::core::array::from_fn(|_| #element))
        }
        Type::Path(p) if p.path.segments.last().is_some_and(|s| s.ident == "Constant") => {
            quote!(<#ty>::new(::core::default::Default::default()))
        }
        _ => quote!(::core::default::Default::default()),
    }
}

fn error(input: &DeriveInput, message: &str) -> proc_macro::TokenStream {
    syn::Error::new_spanned(&input.ident, message).to_compile_error().into()
}
