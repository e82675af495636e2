

module blend(src,dst,mode,color);
    
    // Module arguments
    input wire  [31:0] src;
    input wire  [31:0] dst;
    input wire  [2:0] mode;
    output reg  [31:0] color;
    
    // Stub signals
    reg  [7:0] ch$0$cs;
    reg  [7:0] ch$0$cd;
    reg  [7:0] ch$0$a_s;
    reg  [2:0] ch$0$mode;
    wire  [7:0] ch$0$out;
    reg  [7:0] ch$1$cs;
    reg  [7:0] ch$1$cd;
    reg  [7:0] ch$1$a_s;
    reg  [2:0] ch$1$mode;
    wire  [7:0] ch$1$out;
    reg  [7:0] ch$2$cs;
    reg  [7:0] ch$2$cd;
    reg  [7:0] ch$2$a_s;
    reg  [2:0] ch$2$mode;
    wire  [7:0] ch$2$out;
    reg  [7:0] ch$3$cs;
    reg  [7:0] ch$3$cd;
    reg  [7:0] ch$3$a_s;
    reg  [2:0] ch$3$mode;
    wire  [7:0] ch$3$out;
    
    // Sub module instances
    blend$ch$0 ch$0(
        .cs(ch$0$cs),
        .cd(ch$0$cd),
        .a_s(ch$0$a_s),
        .mode(ch$0$mode),
        .out(ch$0$out)
    );
    blend$ch$1 ch$1(
        .cs(ch$1$cs),
        .cd(ch$1$cd),
        .a_s(ch$1$a_s),
        .mode(ch$1$mode),
        .out(ch$1$out)
    );
    blend$ch$2 ch$2(
        .cs(ch$2$cs),
        .cd(ch$2$cd),
        .a_s(ch$2$a_s),
        .mode(ch$2$mode),
        .out(ch$2$out)
    );
    blend$ch$3 ch$3(
        .cs(ch$3$cs),
        .cd(ch$3$cd),
        .a_s(ch$3$a_s),
        .mode(ch$3$mode),
        .out(ch$3$out)
    );
    
    // Update code
    always @(*) begin
        ch$0$cs = src[(32'h0)+:(8)];
        ch$1$cs = src[(32'h8)+:(8)];
        ch$2$cs = src[(32'h10)+:(8)];
        ch$3$cs = src[(32'h18)+:(8)];
        ch$0$cd = dst[(32'h0)+:(8)];
        ch$1$cd = dst[(32'h8)+:(8)];
        ch$2$cd = dst[(32'h10)+:(8)];
        ch$3$cd = dst[(32'h18)+:(8)];
        ch$0$a_s = src[(32'h18)+:(8)];
        ch$0$mode = mode;
        ch$1$a_s = src[(32'h18)+:(8)];
        ch$1$mode = mode;
        ch$2$a_s = src[(32'h18)+:(8)];
        ch$2$mode = mode;
        ch$3$a_s = src[(32'h18)+:(8)];
        ch$3$mode = mode;
        color = (((ch$3$out) & 32'hffffffff) << 32'h18) | (((ch$2$out) & 32'hffffffff) << 32'h10) | (((ch$1$out) & 32'hffffffff) << 32'h8) | ((ch$0$out) & 32'hffffffff);
    end
    
endmodule // blend


module blend$ch$0(cs,cd,a_s,mode,out);
    
    // Module arguments
    input wire  [7:0] cs;
    input wire  [7:0] cd;
    input wire  [7:0] a_s;
    input wire  [2:0] mode;
    output reg  [7:0] out;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [8:0] mul$b;
    wire  [16:0] mul$p;
    
    // Local signals
    reg  [7:0] inv_a;
    reg  [16:0] base;
    reg  [16:0] prod;
    reg  [16:0] biased;
    reg  [7:0] rounded;
    reg  [7:0] add;
    reg  [8:0] sum;
    
    // Sub module instances
    blend$ch$0$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        base = 32'h0;
        mul$a = ((cs) & 9'h1ff);
        mul$b = ((32'hff) & 9'h1ff);
        add = cd;
        inv_a = ~a_s;
        if (mode == 32'h1) begin
            base = (((cd) & 17'h1ffff) << 32'h8) - ((cd) & 17'h1ffff);
            mul$a = ((cs) & 9'h1ff) - ((cd) & 9'h1ff);
            mul$b = ((a_s) & 9'h1ff);
            add = 32'h0;
        end
        if (mode == 32'h3) begin
            mul$b = ((cd) & 9'h1ff);
            add = 32'h0;
        end
        if (mode == 32'h4) begin
            mul$a = ((cd) & 9'h1ff);
            mul$b = ((inv_a) & 9'h1ff);
            add = cs;
        end
        if (mode == 32'h5) begin
            mul$b = ((a_s) & 9'h1ff);
        end
        prod = base + mul$p;
        biased = prod + 32'h80;
        rounded = (((biased + (biased >> 32'h8)) >> 32'h8) & 8'hff);
        sum = ((rounded) & 9'h1ff) + ((add) & 9'h1ff);
        out = sum[(32'h0)+:(8)];
        if (sum[32'h8]) begin
            out = 32'hff;
        end
        if ((mode == 32'h0) | (mode == 32'h6) | (mode == 32'h7)) begin
            out = cs;
        end
    end
    
endmodule // blend$ch$0


module blend$ch$0$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // blend$ch$0$mul


module blend$ch$1(cs,cd,a_s,mode,out);
    
    // Module arguments
    input wire  [7:0] cs;
    input wire  [7:0] cd;
    input wire  [7:0] a_s;
    input wire  [2:0] mode;
    output reg  [7:0] out;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [8:0] mul$b;
    wire  [16:0] mul$p;
    
    // Local signals
    reg  [7:0] inv_a;
    reg  [16:0] base;
    reg  [16:0] prod;
    reg  [16:0] biased;
    reg  [7:0] rounded;
    reg  [7:0] add;
    reg  [8:0] sum;
    
    // Sub module instances
    blend$ch$1$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        base = 32'h0;
        mul$a = ((cs) & 9'h1ff);
        mul$b = ((32'hff) & 9'h1ff);
        add = cd;
        inv_a = ~a_s;
        if (mode == 32'h1) begin
            base = (((cd) & 17'h1ffff) << 32'h8) - ((cd) & 17'h1ffff);
            mul$a = ((cs) & 9'h1ff) - ((cd) & 9'h1ff);
            mul$b = ((a_s) & 9'h1ff);
            add = 32'h0;
        end
        if (mode == 32'h3) begin
            mul$b = ((cd) & 9'h1ff);
            add = 32'h0;
        end
        if (mode == 32'h4) begin
            mul$a = ((cd) & 9'h1ff);
            mul$b = ((inv_a) & 9'h1ff);
            add = cs;
        end
        if (mode == 32'h5) begin
            mul$b = ((a_s) & 9'h1ff);
        end
        prod = base + mul$p;
        biased = prod + 32'h80;
        rounded = (((biased + (biased >> 32'h8)) >> 32'h8) & 8'hff);
        sum = ((rounded) & 9'h1ff) + ((add) & 9'h1ff);
        out = sum[(32'h0)+:(8)];
        if (sum[32'h8]) begin
            out = 32'hff;
        end
        if ((mode == 32'h0) | (mode == 32'h6) | (mode == 32'h7)) begin
            out = cs;
        end
    end
    
endmodule // blend$ch$1


module blend$ch$1$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // blend$ch$1$mul


module blend$ch$2(cs,cd,a_s,mode,out);
    
    // Module arguments
    input wire  [7:0] cs;
    input wire  [7:0] cd;
    input wire  [7:0] a_s;
    input wire  [2:0] mode;
    output reg  [7:0] out;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [8:0] mul$b;
    wire  [16:0] mul$p;
    
    // Local signals
    reg  [7:0] inv_a;
    reg  [16:0] base;
    reg  [16:0] prod;
    reg  [16:0] biased;
    reg  [7:0] rounded;
    reg  [7:0] add;
    reg  [8:0] sum;
    
    // Sub module instances
    blend$ch$2$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        base = 32'h0;
        mul$a = ((cs) & 9'h1ff);
        mul$b = ((32'hff) & 9'h1ff);
        add = cd;
        inv_a = ~a_s;
        if (mode == 32'h1) begin
            base = (((cd) & 17'h1ffff) << 32'h8) - ((cd) & 17'h1ffff);
            mul$a = ((cs) & 9'h1ff) - ((cd) & 9'h1ff);
            mul$b = ((a_s) & 9'h1ff);
            add = 32'h0;
        end
        if (mode == 32'h3) begin
            mul$b = ((cd) & 9'h1ff);
            add = 32'h0;
        end
        if (mode == 32'h4) begin
            mul$a = ((cd) & 9'h1ff);
            mul$b = ((inv_a) & 9'h1ff);
            add = cs;
        end
        if (mode == 32'h5) begin
            mul$b = ((a_s) & 9'h1ff);
        end
        prod = base + mul$p;
        biased = prod + 32'h80;
        rounded = (((biased + (biased >> 32'h8)) >> 32'h8) & 8'hff);
        sum = ((rounded) & 9'h1ff) + ((add) & 9'h1ff);
        out = sum[(32'h0)+:(8)];
        if (sum[32'h8]) begin
            out = 32'hff;
        end
        if ((mode == 32'h0) | (mode == 32'h6) | (mode == 32'h7)) begin
            out = cs;
        end
    end
    
endmodule // blend$ch$2


module blend$ch$2$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // blend$ch$2$mul


module blend$ch$3(cs,cd,a_s,mode,out);
    
    // Module arguments
    input wire  [7:0] cs;
    input wire  [7:0] cd;
    input wire  [7:0] a_s;
    input wire  [2:0] mode;
    output reg  [7:0] out;
    
    // Stub signals
    reg  [8:0] mul$a;
    reg  [8:0] mul$b;
    wire  [16:0] mul$p;
    
    // Local signals
    reg  [7:0] inv_a;
    reg  [16:0] base;
    reg  [16:0] prod;
    reg  [16:0] biased;
    reg  [7:0] rounded;
    reg  [7:0] add;
    reg  [8:0] sum;
    
    // Sub module instances
    blend$ch$3$mul mul(
        .a(mul$a),
        .b(mul$b),
        .p(mul$p)
    );
    
    // Update code
    always @(*) begin
        base = 32'h0;
        mul$a = ((cs) & 9'h1ff);
        mul$b = ((32'hff) & 9'h1ff);
        add = cd;
        inv_a = ~a_s;
        if (mode == 32'h1) begin
            base = (((cd) & 17'h1ffff) << 32'h8) - ((cd) & 17'h1ffff);
            mul$a = ((cs) & 9'h1ff) - ((cd) & 9'h1ff);
            mul$b = ((a_s) & 9'h1ff);
            add = 32'h0;
        end
        if (mode == 32'h3) begin
            mul$b = ((cd) & 9'h1ff);
            add = 32'h0;
        end
        if (mode == 32'h4) begin
            mul$a = ((cd) & 9'h1ff);
            mul$b = ((inv_a) & 9'h1ff);
            add = cs;
        end
        if (mode == 32'h5) begin
            mul$b = ((a_s) & 9'h1ff);
        end
        prod = base + mul$p;
        biased = prod + 32'h80;
        rounded = (((biased + (biased >> 32'h8)) >> 32'h8) & 8'hff);
        sum = ((rounded) & 9'h1ff) + ((add) & 9'h1ff);
        out = sum[(32'h0)+:(8)];
        if (sum[32'h8]) begin
            out = 32'hff;
        end
        if ((mode == 32'h0) | (mode == 32'h6) | (mode == 32'h7)) begin
            out = cs;
        end
    end
    
endmodule // blend$ch$3


module blend$ch$3$mul(a,b,p);
    
    // Module arguments
    input wire  [8:0] a;
    input wire  [8:0] b;
    output reg  [16:0] p;
    
    // Update code (custom)
    // p = low 17 bits of a * b, both signed: a signed 17-bit context sign-extends
    // both operands before multiplying.
    always @(*) p = $signed(a) * $signed(b);
endmodule // blend$ch$3$mul
