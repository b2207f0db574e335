// Colours: faithful (the article's methods) in warm tones, exact in cool tones, engine-matched
// flights in greens, so the variants are told apart at a glance; several predictions of one
// variant take the next shade.
const FAITHFUL = ['#ff8a1f', '#f0483e', '#ffc21a', '#e0559c', '#c9773a'];
const EXACT = ['#2f9bff', '#1fd1b0', '#8a7dff', '#5fd8ff', '#3f6fd8'];
const ENGINE = ['#5ad35a', '#b5e61d', '#2ecc71', '#8fd694', '#d4f06b'];

export function makePalette() {
    const used = { faithful: 0, exact: 0, engine: 0 };
    return (variant) => {
        const shades = variant === 'faithful' ? FAITHFUL : variant === 'engine' ? ENGINE : EXACT;
        return shades[used[variant]++ % shades.length];
    };
}

export const COLORS = {
    background: 0x1b2029,
    ground: 0x59606c,
    solid: 0x9aa3b2,
    mesh: 0x8e98a8,
    edges: 0x2a303b,
    rest: 0xffe14d,
    danger: 0xff3b3b,
};
