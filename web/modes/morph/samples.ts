/**
 * Key shapes of the morph mode's own (drawn for this project, CC0 like public/samples): closed
 * outlines with corners and smooth joins, one with a hole, one open path.
 */
export interface MorphSample {
  id: string;
  title: string;
  svg: string;
}

const svg = (body: string) => `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200" width="200" height="200">${body}</svg>`;

export const MORPH_SAMPLES: readonly MorphSample[] = [
  {
    id: 'blob',
    title: 'Blob',
    svg: svg('<path fill="#3b6fd8" d="M100 20C150 18 182 52 178 98C175 140 150 182 102 180C58 178 22 150 24 104C26 58 52 22 100 20Z"/>'),
  },
  {
    id: 'star',
    title: 'Star',
    svg: svg('<path fill="#3b6fd8" d="M100 14L122 74L186 76L136 116L154 178L100 142L46 178L64 116L14 76L78 74Z"/>'),
  },
  {
    id: 'heart',
    title: 'Heart',
    svg: svg('<path fill="#3b6fd8" d="M100 178C60 146 18 116 18 72C18 44 40 24 64 24C82 24 94 34 100 48C106 34 118 24 136 24C160 24 182 44 182 72C182 116 140 146 100 178Z"/>'),
  },
  {
    id: 'ring',
    title: 'Ring (with a hole)',
    svg: svg('<path fill="#3b6fd8" fill-rule="evenodd" d="M100 16C146 16 184 54 184 100C184 146 146 184 100 184C54 184 16 146 16 100C16 54 54 16 100 16ZM100 62C79 62 62 79 62 100C62 121 79 138 100 138C121 138 138 121 138 100C138 79 121 62 100 62Z"/>'),
  },
  {
    id: 'square-hole',
    title: 'Frame (square with a hole)',
    svg: svg('<path fill="#3b6fd8" fill-rule="evenodd" d="M24 24H176V176H24ZM70 70V130H130V70Z"/>'),
  },
  {
    id: 'wave',
    title: 'Wave (open path)',
    svg: svg('<path fill="none" stroke="#3b6fd8" stroke-width="8" d="M16 100C46 40 76 40 100 100C124 160 154 160 184 100"/>'),
  },
  {
    id: 'zigzag',
    title: 'Zigzag (open path)',
    svg: svg('<path fill="none" stroke="#3b6fd8" stroke-width="8" d="M16 140L58 60L100 140L142 60L184 140"/>'),
  },
];
